#!/usr/bin/python3
"""Self-weight column plots from scripts/column_study.sh output: the
pressure of every particle against its height at t = 3 s, divided by
rho g H, with the exact line, for standard MPM and the cell theta-bar at
nu = 0.499 on the aligned and the distorted grid (h = 0.25), and the
pressure error against h for every variant.
Usage: plot_column.py STUDY_DIR OUT.png"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
H, rho, g, nu = 10.0, 80.0, 10.0, 0.499


# the finest grid the study ran (0.25 in the full study)
h_fine = min(glob.glob(f"{study}/aligned_{nu}_*_standard"),
             key=lambda d: float(d.split("_")[-2])).split("_")[-2]


def last_csv(run):
    return pd.read_csv(sorted(glob.glob(f"{study}/{run}/particles-*.csv"))[-1])


fig, axes = plt.subplots(1, 5, figsize=(17, 5.5), sharey=False)
panels = [("aligned", "standard"), ("distorted", "standard"),
          ("distorted", "theta-bar"), ("distorted", "node-average")]
for ax, (grid, variant) in zip(axes[:4], panels):
    d = last_csv(f"{grid}_{nu}_{h_fine}_{variant}")
    p = -(d.stress_xx + d.stress_yy + d.stress_zz) / 3 / (rho * g * H)
    ax.plot(p, d.X_y, ".", ms=3, label="particles")
    Y = [0, H]
    p_ex = [(1 + nu) / (3 * (1 - nu)) * (H - y) / H for y in Y]
    ax.plot(p_ex, Y, "k-", label="exact")
    ax.set_title(f"{variant}, {grid} grid")
    ax.set_xlabel("p / (rho g H)")
    ax.set_ylabel("Y [m]")
    ax.legend(loc="upper right")
t = pd.read_csv(f"{study}/table.txt", sep=r"\s+")
ax = axes[4]
for (grid, variant), d in t[t.nu == nu].groupby(["grid", "variant"]):
    ax.loglog(d.h, d.pressure_error, "o-" if grid == "distorted" else "s--",
              label=f"{variant} ({grid})")
ax.set_xticks([0.25, 0.5, 1], ["0.25", "0.5", "1"])
ax.minorticks_off()
ax.set_xlabel("h [m]")
ax.set_ylabel("pressure error / (rho g H)")
ax.set_title(f"nu = {nu}")
ax.legend(fontsize=6, ncol=2, loc="center right")
fig.suptitle("Self-weight column, nu = 0.499, t = 3 s (scripts/column_study.sh)")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
