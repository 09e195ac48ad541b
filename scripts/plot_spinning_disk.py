#!/usr/bin/python3
"""Spinning disk: particles coloured by sigma_rr/sigma0 and sigma_rt/sigma0
at the first and last output. Usage: plot_spinning_disk.py OUTPUT_DIR PNG"""
import glob
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

out_dir, png = sys.argv[1], sys.argv[2]
files = sorted(glob.glob(f"{out_dir}/particles-*.csv"))
if not files:
    sys.exit(f"no particle tables in {out_dir}")
rho, omega, nu, a = 1000.0, 1.0, 0.3, 1.0
sigma0 = rho * omega**2 * (3 + nu) * a**2 / 8

fig, axes = plt.subplots(2, 2, figsize=(10, 9), constrained_layout=True)
for row, f in enumerate([files[0], files[-1]]):
    d = pd.read_csv(f)
    r = np.hypot(d.x, d.y)
    c, s = d.x / np.maximum(r, 1e-300), d.y / np.maximum(r, 1e-300)
    srr = c * c * d.stress_xx + s * s * d.stress_yy + 2 * c * s * d.stress_xy
    srt = (d.stress_yy - d.stress_xx) * c * s + (c * c - s * s) * d.stress_xy
    for col, (val, name) in enumerate([(srr, "sigma_rr"), (srt, "sigma_rt")]):
        ax = axes[row, col]
        sc = ax.scatter(d.x, d.y, c=val / sigma0, s=2, cmap="jet",
                        vmin=-0.2 if col else 0, vmax=0.2 if col else 1)
        ax.set_aspect("equal")
        ax.set_title(f"{name}/sigma0, {f.split('/')[-1]}")
        fig.colorbar(sc, ax=ax, shrink=0.8)
fig.savefig(png, dpi=100)
print(f"wrote {png}")
