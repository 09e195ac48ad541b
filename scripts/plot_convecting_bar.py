#!/usr/bin/python3
"""Convecting bar: RMS stress error / sigma0 and RMS velocity error / v0
over time, standard MPM against the 1D convection correction (stress only,
and stress and body force) and the particle-domain families, 2 and 4
particles per cell, from the
statistics.txt of the runs that run_convecting_bar.sh makes
(FOLDER/ppc{2,4}-{standard,stress-only,correction}/).
Prints the error at the end (after 2 L of travel) and the largest over the
run. Usage: plot_convecting_bar.py FOLDER PNG"""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

folder, png = sys.argv[1], sys.argv[2]
fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True,
                         constrained_layout=True)
print(f"{'run':18s} {'sigma end':>10s} {'sigma max':>10s} "
      f"{'v end':>10s} {'v max':>10s}")
found = 0
for col, ppc in enumerate((2, 4)):
    for variant, style in (("standard", "C3-"), ("stress-only", "C2-"),
                           ("correction", "C0-"), ("uGIMP", "C1--"),
                           ("cpGIMP", "C4--"), ("CPDI", "C5--"),
                           ("CPDI2", "C6:")):
        name = f"ppc{ppc}-{variant}"
        path = os.path.join(folder, name, "statistics.txt")
        if not os.path.exists(path):
            continue
        found += 1
        d = pd.read_csv(path, sep=r"\s+")
        d = d[d.time > 0]  # the exact start would squash the log scale
        s, v = d.sigma_rms_error, d.v_rms_error
        print(f"{name:18s} {s.iloc[-1]:10.4f} {s.max():10.4f} "
              f"{v.iloc[-1]:10.2e} {v.max():10.2e}")
        axes[0, col].semilogy(d.time, s, style, lw=1, label=variant)
        axes[1, col].semilogy(d.time, v.clip(lower=1e-12), style, lw=1,
                              label=variant)
    axes[0, col].axhline(0.01, color="k", ls=":", lw=1, label="1% target")
    axes[0, col].set_title(f"{ppc} particles per cell")
    axes[0, col].set_ylabel("RMS (sigma - exact) / sigma0")
    axes[1, col].set_ylabel("RMS (v - v0) / v0")
    axes[1, col].set_xlabel("t [s]  (travel v0 t = 2 L at the end)")
    axes[0, col].legend()
if not found:
    sys.exit(f"no runs in {folder} (expected ppc2-standard/statistics.txt, ...)")
fig.savefig(png, dpi=100)
print(f"wrote {png}")
