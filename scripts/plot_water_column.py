#!/usr/bin/python3
"""Water column collapse figure from scripts/water_column_study.sh output:
the surge front Z(T) and the height at the wall H(tau) of the runs against
Martin & Moyce (1952) (also h = a/10 and a/40 if the grid study was run),
and the particles coloured by the pressure
p / (rho g 2a) at the output nearest T = 2 (or the last output of a run
that stopped before), without and with theta-bar (cell, and node if
that run is there).
Usage: plot_water_column.py STUDY_DIR OUT.png"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

from water_column_rms import (A, H_DATA, T_DATA, T_SNAPSHOT, TAU_DATA, Z_DATA,
                              cell_pressure, checkerboard_measures, statistics)

study, out = sys.argv[1], sys.argv[2]
runs = [(run, label) for run, label in
        [("standard", "standard MPM"), ("theta-bar", "theta-bar (cell)"),
         ("theta-bar-node", "theta-bar (node)")]
        if os.path.exists(f"{study}/{run}/statistics.txt")]
rho, g = 1000.0, 9.81

# top: the two curves side by side; bottom: one pressure panel per run
fig = plt.figure(figsize=(7 * max(2, len(runs)), 8.5))
grid = fig.add_gridspec(2, 6, height_ratios=[1.4, 1])
ax_z, ax_h = fig.add_subplot(grid[0, :3]), fig.add_subplot(grid[0, 3:])
ax_z.plot(T_DATA, Z_DATA, "ko", label="Martin & Moyce 1952")
ax_h.plot(TAU_DATA, H_DATA, "ko", label="Martin & Moyce 1952")
for (run, label), style in zip(runs, ["-", "--", "-"]):
    s = statistics(f"{study}/{run}")
    ax_z.plot(s["T"], s["Z"], style, label=label)
    ax_h.plot(s["tau"], s["H"], style, label=label)


def finish_curves(ax_z, ax_h):
    ax_z.set(xlim=(0, 3.6), ylim=(0.9, 4.6), xlabel="T = t sqrt(2g/a)",
             ylabel="Z = x_front / a", title="surge front")
    ax_h.set(xlim=(0, 7.8), ylim=(0, 1.05), xlabel="tau = t sqrt(g/a)",
             ylabel="H = h / (2a)", title="height at the wall")
    ax_z.legend(fontsize=8)
    ax_h.legend(fontsize=8)


finish_curves(ax_z, ax_h)

for i, (run, label) in enumerate(runs):
    w = 6 // len(runs)
    ax = fig.add_subplot(grid[1, i * w:(i + 1) * w])
    s = statistics(f"{study}/{run}")
    k = int((s["T"] - T_SNAPSHOT).abs().idxmin())
    table = sorted(glob.glob(f"{study}/{run}/particles-*.csv"))[k]
    d = pd.read_csv(table)
    mode = checkerboard_measures(cell_pressure(f"{study}/{run}", table))[1]
    p = -(d.stress_xx + d.stress_yy + d.stress_zz) / 3 / (rho * g * 2 * A)
    sc = ax.scatter(d.x / A, d.y / A, c=p, s=4, cmap="viridis",
                    vmin=-0.2, vmax=1.2)
    ax.set_aspect("equal")
    ax.set(xlim=(0, 4.6), ylim=(0, 2.1), xlabel="x / a", ylabel="y / a",
           title=f"{label}: p / (rho g 2a) at T = {s['T'][k]:.2f}\n"
                 f"checkerboard {s.checkerboard[k]:.3f}, its 2x2 mode {mode:.3f}")
    fig.colorbar(sc, ax=ax, fraction=0.025, pad=0.02)
fig.suptitle("Water column collapse, h = a/20, 2x2 particles per cell "
             "(scripts/water_column_study.sh)")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")

# The grid studies (water_column_study.sh OUT grid / fine), if they ran:
# their own figure, <out>_grids.png, beside the h = a/20 runs.
grid_runs = [(run, label, style) for run, label, style in
             [("standard", "standard, h = a/20", "-"),
              ("theta-bar-node", "node, h = a/20", "-"),
              ("standard_h10", "standard, h = a/10", ":"),
              ("standard_h40", "standard, h = a/40", "-."),
              ("theta-bar-node_h10", "node, h = a/10", ":"),
              ("theta-bar-node_h40", "node, h = a/40", "-."),
              ("theta-bar-node_h80", "node, h = a/80", "--"),
              ("theta-bar-node_h160", "node, h = a/160", "--")]
             if os.path.exists(f"{study}/{run}/statistics.txt")]
if any("_h" in run for run, _, _ in grid_runs):
    fig, (ax_z, ax_h) = plt.subplots(1, 2, figsize=(14, 5))
    ax_z.plot(T_DATA, Z_DATA, "ko", label="Martin & Moyce 1952")
    ax_h.plot(TAU_DATA, H_DATA, "ko", label="Martin & Moyce 1952")
    for run, label, style in grid_runs:
        s = statistics(f"{study}/{run}")
        ax_z.plot(s["T"], s["Z"], style, lw=1, label=label)
        ax_h.plot(s["tau"], s["H"], style, lw=1, label=label)
    finish_curves(ax_z, ax_h)
    fig.suptitle("Water column collapse on finer and coarser grids "
                 "(scripts/water_column_study.sh OUT grid, OUT fine)")
    fig.tight_layout()
    grids_out = os.path.splitext(out)[0] + "_grids.png"
    fig.savefig(grids_out, dpi=110)
    print(f"wrote {grids_out}")
