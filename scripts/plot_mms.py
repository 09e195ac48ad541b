#!/usr/bin/python3
"""Manufactured-solution convergence plot from scripts/mms_study.sh: (a) the
L2 and (b) the maximum displacement error at t = T and (c) the largest L2
error over the period (sampled every T/20), over G, against h, log-log, one colour per shape-function family, one marker per G (solid 2D,
dashed 3D), with a slope-2 reference line.

It also recomputes both errors of every run from its final particle CSV
(x - X against the exact displacement at the final time, V0-weighted) and
prints the largest difference from the statistics file, so the figure's
numbers are checked against the particle output.
Usage: plot_mms.py OUT.png STUDY_DIR [STUDY_DIR ...]
(default OUT doc/figures/manufactured_solution.png, STUDY_DIR results/mms)"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

out = sys.argv[1] if len(sys.argv) > 1 else "doc/figures/manufactured_solution.png"
studies = sys.argv[2:] or ["results/mms"]
E, rho = 1e7, 1000.0
c = np.sqrt(E / rho)


def recomputed_errors(run):
    """(L2, max) / G from the last particle CSV of a run directory."""
    G = float(run.rsplit("_G", 1)[1].split("_n")[0])
    stats = pd.read_csv(f"{run}/statistics.txt", sep=r"\s+")
    t = stats.time.iloc[-1]
    p = pd.read_csv(sorted(glob.glob(f"{run}/particles-*.csv"))[-1])
    dim = 3 if "z" in p.columns else 2
    err2 = np.zeros(len(p))
    for d, axis in enumerate("xyz"[:dim]):
        X = p[f"X_{axis}"]
        u = G * np.sin(np.pi * X) * np.sin(c * np.pi * t + (0 if d == 0 else np.pi))
        err2 += (p[axis] - X - u) ** 2
    l2 = np.sqrt((p.volume0 * err2).sum() / p.volume0.sum()) / G
    return l2, np.sqrt(err2.max()) / G, stats.u_L2_error.iloc[-1], stats.u_max_error.iloc[-1]


frames = []
worst = 0.0
for study in studies:
    frames.append(pd.read_csv(f"{study}/errors.csv"))
    for run in sorted(glob.glob(f"{study}/*d_*_G*_n*")):
        if not os.path.exists(f"{run}/statistics.txt") or not glob.glob(f"{run}/particles-*.csv"):
            continue
        l2, mx, l2_stat, mx_stat = recomputed_errors(run)
        # the CSV has 10 significant digits of x and X: compare to 1e-9 absolute
        worst = max(worst, abs(l2 - l2_stat), abs(mx - mx_stat))
print(f"largest difference, statistics against the particle CSVs (/G): {worst:.2e}")

data = pd.concat(frames)
data = data[data.u_L2_error != "failed"].astype({"u_L2_error": float})
fig, axes = plt.subplots(1, 3, figsize=(17, 5))
families = list(dict.fromkeys(data.family))
Gs = sorted(data.G.unique())
markers = ["o", "s", "^", "D"]
hs = np.array(sorted(data.h.unique()))
for ax, column, name in [(axes[0], "u_L2_error", "(a) L2 error at t = T"),
                         (axes[1], "u_max_error", "(b) maximum error at t = T"),
                         (axes[2], "u_L2_peak", "(c) largest L2 error over the period")]:
    for (dim, family, G), d in data.groupby(["dim", "family", "G"], sort=False):
        d = d.sort_values("h")
        ax.loglog(d.h, d[column].astype(float),
                  marker=markers[Gs.index(G) % len(markers)],
                  ls="-" if dim == 2 else "--",
                  color=f"C{families.index(family)}",
                  label=f"{family}, G = {G:g}" + (", 3D" if dim == 3 else ""))
    # below the lowest curve at the coarsest h, so that it stays visible
    ref = 0.5 * data[data.h == hs.max()][column].astype(float).min()
    ax.loglog(hs, ref * (hs / hs.max()) ** 2, "k:", label="slope 2")
    ax.set_xlabel("h [m]")
    ax.set_ylabel("displacement error / G")
    ax.set_title(name)
    ax.grid(True, which="both", lw=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=120)
print(f"wrote {out}")
