#!/usr/bin/python3
"""Travel of the rolling cylinder's centre against time
(scripts/sliding_block_study.sh): without and with the gap check, each
friction coefficient on both grids, and the exact rigid cylinder (rolling
for mu >= tan(theta)/3, sliding below)."""
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

work, out = sys.argv[1], sys.argv[2]
theta, g = math.radians(30), 9.81
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
fig, axes = plt.subplots(1, 2, figsize=(9, 3.8), sharey=True)
for ax, gap in zip(axes, ("false", "true")):
    mus = sorted({float(f.split("_")[2]) for f in os.listdir(work)
                  if f.startswith(f"cylinder_{gap}_")})
    for k, mu in enumerate(mus):
        for refine, style in ((1, "-"), (2, "--")):
            name = os.path.join(work, f"cylinder_{gap}_{mu:g}_{refine}.txt")
            if not os.path.exists(name):
                continue
            rows = [l.split() for l in open(name)]
            head = rows[0]
            t = [float(r[head.index("time")]) for r in rows[1:]]
            s = [float(r[head.index("slide")]) for r in rows[1:]]
            ax.plot(t, s, style, color=colours[k % len(colours)],
                    label=f"mu = {mu:g}" if refine == 1 else None)
        a = (g * math.sin(theta) / 1.5 if mu >= math.tan(theta) / 3 else
             g * (math.sin(theta) - mu * math.cos(theta)))
        tt = [0.5 * i / 50 for i in range(51)]
        ax.plot(tt, [0.5 * a * x * x for x in tt], ":", color="k",
                linewidth=0.8)
    ax.set_xlabel("t [s]")
    ax.set_title(f"Gap check = {gap}", fontsize=9)
axes[0].set_ylabel("travel of the centre [m]")
axes[0].legend(fontsize=8)
fig.suptitle("Cylinder on a plane at 30 deg: h = 0.05 (solid), 0.025 "
             "(dashed), exact rigid cylinder (dotted)", fontsize=9)
fig.tight_layout()
fig.savefig(out, dpi=120)
