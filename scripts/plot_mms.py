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
# One panel per dimension and amplitude, one line per family: the L2 error
# at t = T (solid) and its largest value over the period (dotted).
dims = sorted(data.dim.unique())
Gs = sorted(data.G.unique())
families = list(dict.fromkeys(data.family))
fig, axes = plt.subplots(len(dims), len(Gs), figsize=(6 * len(Gs), 4.5 * len(dims)),
                         squeeze=False)
for r, dim in enumerate(dims):
    for c, G in enumerate(Gs):
        ax = axes[r, c]
        sub = data[(data.dim == dim) & (data.G == G)]
        for family, d in sub.groupby("family", sort=False):
            d = d.sort_values("h")
            color = f"C{families.index(family)}"
            ax.loglog(d.h, d.u_L2_error, "o-", color=color, label=family)
            ax.loglog(d.h, d.u_L2_peak.astype(float), ":", color=color)
        hs = np.array(sorted(sub.h.unique()))
        if len(hs):
            ref = 0.5 * sub[sub.h == hs.max()].u_L2_error.min()
            ax.loglog(hs, ref * (hs / hs.max()) ** 2, "k--", lw=1, label="slope 2")
        ax.set_title(f"{dim}D, G = {G:g}: L2 error at T (solid), largest over the period (dotted)",
                     fontsize=9)
        ax.set_xlabel("h [m]")
        ax.set_ylabel("displacement error / G")
        ax.grid(True, which="both", lw=0.3)
        ax.legend(fontsize=8, loc="lower right")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
