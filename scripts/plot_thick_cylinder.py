#!/usr/bin/python3
"""Thick-walled cylinder plots from scripts/thick_cylinder_study.sh output:
(a) the mean radial displacement of the inner particles over the exact one
against nu for every variant (solid: the finest h of the study, dashed: the
coarsest), and the pressure of every particle against its material radius
at t = 0.8 s, divided by p, with the exact (uniform) value, for (b)
standard MPM and (c) the cell theta-bar at nu = 0.4999 on the finest h.
Usage: plot_thick_cylinder.py STUDY_DIR OUT.png"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
a, b, p = 1.0, 2.0, 1e3
nu_max = 0.4999

t = pd.read_csv(f"{study}/table.txt", sep=r"\s+")
t = t[t.ur_inner_ratio != "failed"].astype({"ur_inner_ratio": float})
hs = sorted(t.h.unique())
fig, axes = plt.subplots(1, 3, figsize=(16, 5))

# (a) against 1/(1-2nu), the growth of the bulk over the shear modulus
ax = axes[0]
for i, (variant, d) in enumerate(t.groupby("variant", sort=False)):
    for h in hs:
        dh = d[d.h == h].sort_values("nu")
        ax.semilogx(1 / (1 - 2 * dh.nu), dh.ur_inner_ratio,
                    "o-" if h == hs[0] else "s--", color=f"C{i}",
                    label=f"{variant}, h = {h}")
nus = sorted(t.nu.unique())
ax.set_xticks([1 / (1 - 2 * nu) for nu in nus])
ax.set_xticklabels([f"{nu:g}" for nu in nus])
ax.minorticks_off()
ax.axhline(1, color="k", lw=0.8)
ax.set_xlabel("nu")
ax.set_ylabel("u_r(inner) / exact")
ax.set_title("(a) inner radial displacement")
ax.legend(fontsize=7)


def last_csv(run):
    return pd.read_csv(sorted(glob.glob(f"{study}/{run}/particles-*.csv"))[-1])


k = p * a * a / (b * b - a * a)
p_exact = (1 + nu_max) * 2 * k / 3 / p  # -p_exact/p: the pressure is tensile
for ax, variant, tag in [(axes[1], "standard", "(b)"),
                         (axes[2], "theta-bar", "(c)")]:
    d = last_csv(f"{nu_max}_{hs[0]}_{variant}")
    R = np.hypot(d.X_x, d.X_y)
    pressure = -(d.stress_xx + d.stress_yy + d.stress_zz) / 3 / p
    ax.plot(R, pressure, ".", ms=2, label="particles")
    ax.axhline(-p_exact, color="k", label="exact")
    ax.set_xlabel("R [m]")
    ax.set_ylabel("pressure / p")
    ax.set_title(f"{tag} {variant}, nu = {nu_max}, h = {hs[0]}")
    ax.legend(loc="upper right")
fig.suptitle("Thick-walled cylinder under internal pressure, plane strain, "
             "t = 0.8 s (scripts/thick_cylinder_study.sh)")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
