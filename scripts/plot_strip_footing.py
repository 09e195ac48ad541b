#!/usr/bin/python3
"""Strip footing load-settlement curves from scripts/strip_footing_study.sh
output (OUT/<variant>_<h>.txt: settlement/B, q/c_u): standard MPM,
theta-bar and the filter on every grid of the study, with Prandtl's limit (2 + pi) c_u,
one panel per shape-function family (variant names remedy-family, e.g.
theta-bar-CPDI; no suffix: standard; the suffixes -fixed and
-small-strain, Implicit solver/Geometry = fixed and small strain, and
-graded, the graded grids, make panels of their own). A curve ends where its run stopped.
Usage: plot_strip_footing.py STUDY_DIR OUT.png"""
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
styles = {"standard": "C3", "theta-bar": "C0", "filter": "C2"}
curves = {}  # family -> [(remedy, h, file)]
for f in glob.glob(f"{study}/*_*.txt"):
    variant, h = os.path.basename(f)[:-4].rsplit("_", 1)
    for remedy in styles:
        if variant == remedy or variant.startswith(remedy + "-"):
            family = variant[len(remedy) + 1:] or "standard"
            curves.setdefault(family, []).append((remedy, float(h), f))
families = sorted(curves, key=lambda f: (f != "standard", f))
fig, axes = plt.subplots(1, len(families), figsize=(7 * len(families), 5),
                         squeeze=False)
for ax, family in zip(axes[0], families):
    for remedy in styles:
        runs = sorted((c for c in curves[family] if c[0] == remedy),
                      key=lambda c: -c[1])
        for k, (_, h, f) in enumerate(runs):
            d = pd.read_csv(f, sep=r"\s+")
            ax.plot(d.settlement_over_B, d.q_over_cu, ["-", "--", ":", "-."][k % 4],
                    color=styles[remedy], label=f"{remedy}, h = {h:g} B")
    ax.axhline(2 + math.pi, color="k", lw=0.8)
    ax.text(0.01, 2 + math.pi + 0.1, "Prandtl: (2 + $\\pi$) $c_u$")
    ax.set_xlabel("settlement / B")
    ax.set_ylabel("bearing pressure q / $c_u$")
    ax.set_xlim(0, 0.5)
    ax.set_ylim(0, 12)
    ax.legend(loc="lower right", ncol=2, fontsize="small")
    parts = family.split("-")
    geometry_words = ("fixed", "small", "strain", "graded")
    title = "-".join(p for p in parts if p not in geometry_words)
    title = f"{title or 'standard'} family, "
    title += ("small strain" if "small" in parts else
              "fixed geometry" if "fixed" in parts else "updated geometry")
    if "graded" in parts:
        title += ", graded grids (h: finest cells)"
    ax.set_title(title)
fig.suptitle("smooth rigid strip footing, von Mises, $\\nu$ = 0.49, quasi-static")
fig.tight_layout()
fig.savefig(out, dpi=120)
