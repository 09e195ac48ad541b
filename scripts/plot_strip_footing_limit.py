#!/usr/bin/python3
"""The strip footing's limit load against the grid: from a
scripts/strip_footing_study.sh run with GEOMETRY="small strain" or fixed
(OUT/<variant>_<h>.txt,
settlement/B and q/c_u), the last q of each run, that is the limit load of
the discretization once the curve is level, as its distance from Prandtl's
(2 + pi) c_u against the cell size h, one line per remedy, with a slope-one
line. A run whose q spans more than 0.1% over the last third of its steps
(no limit load: standard MPM still rising, or a q that alternates) is
drawn with an open marker. Prints the table.
Usage: plot_strip_footing_limit.py STUDY_DIR OUT.png"""
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
prandtl = 2 + math.pi
runs = {}  # variant -> [(h, q, rising)]
for f in glob.glob(f"{study}/*_*.txt"):
    variant, h = os.path.basename(f)[:-4].rsplit("_", 1)
    d = pd.read_csv(f, sep=r"\s+")
    q = d.q_over_cu.to_numpy()
    last = q[-(len(q) // 3):]
    change = (last.max() - last.min()) / q[-1]
    runs.setdefault(variant, []).append((float(h), q[-1], change))
colors = {"theta-bar": "C0", "node": "C1", "filter": "C2", "standard": "C3"}
fig, ax = plt.subplots(figsize=(6, 4.5))
print("| variant | h | q/c_u | q / Prandtl's - 1 | level |")
print("|---|---|---|---|---|")
for variant in sorted(runs):
    pts = sorted(runs[variant], reverse=True)
    remedy = next((r for r in colors if variant.startswith(r)), None)
    for h, q, change in pts:
        level = "yes" if abs(change) <= 1e-3 else \
            f"no: q spans {change:.2%} over the last third of the steps"
        print(f"| {variant} | {h:g} | {q:.3f} | {q / prandtl - 1:+.2%} | "
              f"{level} |")
    line, = ax.loglog([p[0] for p in pts],
                      [abs(p[1] / prandtl - 1) for p in pts], "-",
                      color=colors.get(remedy, "k"),
                      label=variant.split("-small-strain")[0].split("-fixed")[0])
    for h, q, change in pts:
        ax.loglog(h, abs(q / prandtl - 1), "o", color=line.get_color(),
                  mfc=line.get_color() if abs(change) <= 1e-3 else "none")
hs = sorted({p[0] for v in runs.values() for p in v})
ax.loglog(hs, [0.4 * h for h in hs], "k:", label="slope 1")
ax.axhline(0.02, color="grey", lw=0.8)
ax.text(hs[0], 0.021, "2%", color="grey")
ax.set_xlabel("h / B (cells over the collapse mechanism)")
ax.set_ylabel("|q / ((2 + $\\pi$) $c_u$) - 1|")
ax.set_title("strip footing: limit load, " +
             ("small strain" if any("small-strain" in v for v in runs) else
              "fixed geometry"))
ax.legend()
fig.tight_layout()
fig.savefig(out, dpi=120)
