#!/usr/bin/python3
"""Strip footing load-settlement curves from scripts/strip_footing_study.sh
output (OUT/<variant>_<h>.txt: settlement/B, q/c_u): standard MPM and
theta-bar on every grid of the study, with Prandtl's limit (2 + pi) c_u. A
curve ends where its run stopped.
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
fig, ax = plt.subplots(figsize=(7, 5))
styles = {"standard": "C3", "theta-bar": "C0"}
files = sorted(glob.glob(f"{study}/*_*.txt"),
               key=lambda f: (f.split("/")[-1].split("_")[0],
                              -float(f.rsplit("_", 1)[1][:-4])))
dashes = {}
for f in files:
    name = os.path.basename(f)[:-4]
    variant, h = name.rsplit("_", 1)
    if variant not in styles:
        continue
    d = pd.read_csv(f, sep=r"\s+")
    hs = dashes.setdefault(variant, [])
    hs.append(h)
    ls = ["-", "--", ":"][len(hs) - 1] if len(hs) <= 3 else "-"
    ax.plot(d.settlement_over_B, d.q_over_cu, ls, color=styles[variant],
            label=f"{variant}, h = {h} B")
ax.axhline(2 + math.pi, color="k", lw=0.8)
ax.text(0.01, 2 + math.pi + 0.1, "Prandtl: (2 + $\\pi$) $c_u$")
ax.set_xlabel("settlement / B")
ax.set_ylabel("bearing pressure q / $c_u$")
ax.set_xlim(0, 0.5)
ax.set_ylim(0, 12)
ax.legend(loc="lower right")
ax.set_title("smooth rigid strip footing, von Mises, $\\nu$ = 0.49, quasi-static")
fig.tight_layout()
fig.savefig(out, dpi=120)
