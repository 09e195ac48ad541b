#!/usr/bin/python3
"""Axial bar (doc/benchmarks/axial_bar.md) from scripts/axial_bar_study.sh:
(a) the centre-of-mass velocity over v0 against time, with the exact
v0 cos(omega t)/(beta L); (b) the mass-weighted RMS velocity error over v0
against time. Writes OUT/table.txt: for each run the largest
|v_cm - exact|/v0 and RMS error over the run, and both at the end.
Usage: plot_axial_bar.py OUT PNG"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

out, png = sys.argv[1], sys.argv[2]
v0 = 0.1
runs = sorted(glob.glob(f"{out}/*_n*/statistics.txt"))
if not runs:
    sys.exit(f"no runs in {out}")
fig, (a, b) = plt.subplots(1, 2, figsize=(11, 4))
lines = [f"{'run':<14} {'max |v_cm-exact|/v0':>20} {'max v_rms_error':>16} "
         f"{'end |v_cm-exact|/v0':>20} {'end v_rms_error':>16}"]
for f in runs:
    name = os.path.basename(os.path.dirname(f))
    d = pd.read_csv(f, sep=r"\s+")
    cm = (d.v_cm - d.v_cm_exact).abs() / v0
    style = "-" if name.endswith("_n16") else "--"
    color = {"standard": "C0", "uGIMP": "C1", "CPDI": "C2"}.get(name.split("_")[0], "C3")
    a.plot(d.time, d.v_cm / v0, style, color=color, label=name)
    b.plot(d.time, d.v_rms_error, style, color=color, label=name)
    lines.append(f"{name:<14} {cm.max():20.3e} {d.v_rms_error.max():16.3e} "
                 f"{cm.iloc[-1]:20.3e} {d.v_rms_error.iloc[-1]:16.3e}")
a.plot(d.time, d.v_cm_exact / v0, "k:", lw=2, label="exact")
a.set_xlabel("t [s]")
a.set_ylabel("v_cm / v0")
a.legend(fontsize=7)
b.set_xlabel("t [s]")
b.set_ylabel("RMS (v_p - v(X_p, t)) / v0")
b.legend(fontsize=7)
for ax in (a, b):
    ax.grid(lw=0.3)
fig.suptitle("Axial bar, fixed-free, E = 100, L = 25, rho = 1, v0 = 0.1 (16 and 32 cells, 2 ppc)")
fig.tight_layout()
fig.savefig(png, dpi=110)
open(f"{out}/table.txt", "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
print(f"wrote {png}")
