#!/usr/bin/python3
"""Spinning disk, the seed's pictures: particles coloured by sigma_rr/sigma0
(top row) and sigma_rt/sigma0 (bottom row) at the last output, one column
per variant. Usage: plot_spinning_disk_variants.py STUDY_DIR PNG VARIANT..."""
import glob
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

study, png, variants = sys.argv[1], sys.argv[2], sys.argv[3:]
rho, omega, nu, a = 1000.0, 1.0, 0.3, 1.0
sigma0 = rho * omega**2 * (3 + nu) * a**2 / 8

fig, axes = plt.subplots(2, len(variants), figsize=(2.6 * len(variants), 5.6),
                         constrained_layout=True, squeeze=False)
for col, v in enumerate(variants):
    files = sorted(glob.glob(f"{study}/{v}/output/particles-*.csv"))
    for row in range(2):
        axes[row, col].set_axis_off()
    if not files:
        axes[0, col].set_title(f"{v}\n(failed)", fontsize=9)
        continue
    d = pd.read_csv(files[-1])
    r = np.hypot(d.x, d.y)
    c, s = d.x / np.maximum(r, 1e-300), d.y / np.maximum(r, 1e-300)
    srr = c * c * d.stress_xx + s * s * d.stress_yy + 2 * c * s * d.stress_xy
    srt = (d.stress_yy - d.stress_xx) * c * s + (c * c - s * s) * d.stress_xy
    exact = rho * omega**2 / 8 * (3 + nu) * (a**2 - r**2)
    t = files[-1]
    for row, (val, lim, name) in enumerate(
            [(srr / sigma0, (0, 1), "sigma_rr"), (srt / sigma0, (-0.2, 0.2), "sigma_rt")]):
        ax = axes[row, col]
        sc = ax.scatter(d.x, d.y, c=val, s=0.3, cmap="jet", vmin=lim[0], vmax=lim[1])
        ax.set_aspect("equal")
        if row == 0:
            rms = np.sqrt(np.average(((srr - exact) / sigma0) ** 2, weights=d.mass))
            ax.set_title(f"{v}\nrms err {rms:.3f}", fontsize=9)
        else:
            rms = np.sqrt(np.average((srt / sigma0) ** 2, weights=d.mass))
            ax.set_title(f"rms {rms:.3f}", fontsize=9)
        if col == len(variants) - 1:
            fig.colorbar(sc, ax=ax, shrink=0.7, label=f"{name}/sigma0")
fig.savefig(png, dpi=110)
print(f"wrote {png}")
