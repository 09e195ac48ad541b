#!/usr/bin/python3
"""Slide of the block against time (scripts/sliding_block_study.sh): each
friction coefficient's run on both grids, and the exact slide."""
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

work, out = sys.argv[1], sys.argv[2]
fig, ax = plt.subplots(figsize=(6.5, 4.2))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
files = sorted(glob.glob(os.path.join(work, "stats_*_1.txt")),
               key=lambda f: float(os.path.basename(f).split("_")[1]))
for k, f in enumerate(files):
    mu = float(os.path.basename(f).split("_")[1])
    for refine, style in ((1, "-"), (2, "--")):
        name = os.path.join(work, f"stats_{os.path.basename(f).split('_')[1]}_{refine}.txt")
        rows = [l.split() for l in open(name)]
        head = rows[0]
        t = [float(r[head.index("time")]) for r in rows[1:]]
        s = [float(r[head.index("slide")]) for r in rows[1:]]
        ax.plot(t, s, style, color=colours[k % len(colours)],
                label=f"mu = {mu:g}" if refine == 1 else None)
    theta = math.radians(30)
    a = max(0.0, 9.81 * (math.sin(theta) - mu * math.cos(theta)))
    tt = [0.5 * i / 50 for i in range(51)]
    ax.plot(tt, [0.5 * a * x * x for x in tt], ":", color="k",
            linewidth=0.8)
ax.set_xlabel("t [s]")
ax.set_ylabel("slide [m]")
ax.set_title("Sliding block, theta = 30 deg: h = 0.05 (solid), 0.025 "
             "(dashed), exact (dotted)", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(out, dpi=120)
