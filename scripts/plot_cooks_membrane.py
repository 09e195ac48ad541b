#!/usr/bin/python3
"""Cook's membrane plots from scripts/cooks_membrane_study.sh output:
the tip displacement u_y(48,60) over the FE reference for every variant
and grid, (a) plane stress and (b) plane strain at nu = 0.4999 (the band
is the 1% target), and the particles of (b) in the final state on the
finest grid, coloured by the pressure -(s_xx + s_yy + s_zz)/3, for
standard MPM and theta-bar (displacements magnified). Grids without
every variant (extra runs) show only the bars they have.
Usage: plot_cooks_membrane.py STUDY_DIR OUT.png"""
import glob
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
t = pd.read_csv(f"{study}/table.csv")
t = t[t.corner_ratio != "failed"].astype({"corner_ratio": float})
hs = sorted(t.h.unique(), reverse=True)
variants = list(dict.fromkeys(t.variant))

fig = plt.figure(figsize=(16, 9))
for k, case in enumerate(["a", "b"]):
    ax = fig.add_subplot(2, 2, k + 1)
    d = t[t.case == case]
    width = 0.8 / len(hs)
    for j, h in enumerate(hs):
        rows = [d[(d.h == h) & (d.variant == v)] for v in variants]
        r = [row.corner_ratio.mean() for row in rows]
        # not at rest: corner_ratio still changed by more than 1e-3 over
        # the last tenth of the run
        moving = [len(row) > 0 and float(row.last_change.iloc[0]) > 1e-3
                  for row in rows]
        x = np.arange(len(variants)) + (j - (len(hs) - 1) / 2) * width
        bars = ax.bar(x, r, width, label=f"h = {h:g}", color=f"C{j}")
        for bar, m in zip(bars, moving):
            if m:
                bar.set_hatch("//")
                bar.set_edgecolor("k")
        for xi, ri in zip(x, r):
            if np.isfinite(ri):
                ax.text(xi, ri + 0.005, f"{ri:.3f}", ha="center",
                        va="bottom", fontsize=7, rotation=90)
    ax.axhspan(0.99, 1.01, color="0.8", zorder=0, label="1% target")
    ax.axhline(1, color="k", lw=0.8)
    ax.set_xticks(np.arange(len(variants)))
    ax.set_xticklabels(variants, rotation=20, fontsize=8)
    lo = min(0.5, np.nanmin(d.corner_ratio) - 0.05)
    ax.set_ylim(lo, 1.12)
    ax.set_ylabel("u_y(48,60) / FE reference")
    ax.set_title("(a) plane stress, nu = 1/3" if case == "a" else
                 "(b) plane strain, nu = 0.4999")
    ax.bar([np.nan], [np.nan], hatch="//", color="w", edgecolor="k",
           label="not at rest")
    ax.legend(fontsize=8, loc="upper left", ncol=5)


def last_csv(run):
    return pd.read_csv(sorted(glob.glob(f"{study}/{run}/particles-*.csv"))[-1])


# the finest grid with both runs (the study's extra h = 1 runs of (b) have
# no standard run)
h = min(x for x in hs
        if glob.glob(f"{study}/b_{x:g}_standard/particles-*.csv")
        and glob.glob(f"{study}/b_{x:g}_theta-bar/particles-*.csv"))
runs = [(f"b_{h:g}_standard", "standard"), (f"b_{h:g}_theta-bar", "theta-bar")]
data = [last_csv(r) for r, _ in runs]
pressures = [-(d.stress_xx + d.stress_yy + d.stress_zz) / 3 for d in data]
lim = np.percentile(np.abs(pressures[1]), 99)
for k, ((run, name), d, p) in enumerate(zip(runs, data, pressures)):
    ax = fig.add_subplot(2, 2, 3 + k)
    ux, uy = d.x - d.X_x, d.y - d.X_y
    scale = 4 / np.abs(uy).max()  # the tip moves by 4
    sc = ax.scatter(d.X_x + scale * ux, d.X_y + scale * uy, c=p, s=3,
                    cmap="coolwarm", vmin=-lim, vmax=lim)
    ax.plot([0, 48, 48, 0, 0], [0, 44, 60, 44, 0], "k-", lw=0.5)
    ax.set_aspect("equal")
    ax.set_title(f"(b) {name}, h = {h:g}: pressure (range +-{lim:.2g}; "
                 f"|p| up to {np.abs(p).max():.2g}), "
                 f"u x {scale:.0f}", fontsize=9)
    fig.colorbar(sc, ax=ax, shrink=0.8)
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
