#!/usr/bin/python3
"""Read what mpm wrote with pandas and check it against the documentation:
statistics.txt columns, particles-NNNNN.csv columns and id order, and the
.pvd records pointing to existing .pvtu files."""
import glob
import os
import re
import sys

import pandas as pd

out = sys.argv[1]
fail = []

stats = pd.read_csv(f"{out}/statistics.txt", sep=r"\s+")
expected = ["time", "step", "dt", "n_particles", "mass", "removed_mass",
            "kinetic_energy", "strain_energy", "total_energy", "momentum_x",
            "momentum_y", "angular_momentum_z"]
if list(stats.columns) != expected:
    fail.append(f"statistics columns {list(stats.columns)}")
if len(stats) != 3 or abs(stats.time.iloc[-1] - 0.01) > 1e-12:
    fail.append(f"statistics rows {stats.time.tolist()}")
if stats.n_particles.nunique() != 1 or stats.n_particles.iloc[0] != 32:
    fail.append("particle count")

tables = sorted(glob.glob(f"{out}/particles-*.csv"))
if len(tables) != 3:
    fail.append(f"{len(tables)} particle tables")
for t in tables:
    d = pd.read_csv(t)
    for c in ["id", "x", "y", "mass", "volume0", "volume", "body", "v_x",
              "v_y", "X_x", "X_y", "stress_xx", "stress_yy", "stress_zz",
              "stress_yz", "stress_xz", "stress_xy", "F_xx", "F_xy", "F_yx",
              "F_yy", "traction_area", "equivalent_plastic_strain"]:
        if c not in d.columns:
            fail.append(f"{t}: no column {c}")
    if not d.id.is_monotonic_increasing or d.id.nunique() != len(d):
        fail.append(f"{t}: ids not sorted and unique")
    if sorted(d.body.unique()) != [0, 1]:
        fail.append(f"{t}: bodies {d.body.unique()}")

for series in ["particles", "grid"]:
    pvd = open(f"{out}/{series}.pvd").read()
    files = re.findall(r'file="([^"]+)"', pvd)
    if len(files) != 3:
        fail.append(f"{series}.pvd lists {len(files)} files")
    for f in files:
        if not os.path.exists(os.path.join(out, f)):
            fail.append(f"{series}.pvd: {f} missing")

if fail:
    print("FAIL:\n  " + "\n  ".join(fail))
    sys.exit(1)
print("OK: statistics, particle tables and ParaView records read back")
