#!/usr/bin/python3
"""Thick cylinder by the quasi-static integrator, from the table that
scripts/thick_cylinder_implicit.sh prints: the inner radial displacement
over Lame's against nu (axis 1/(1 - 2 nu), the bulk over the shear
modulus) for standard MPM, theta-bar and the node average on every grid
of the table.
Usage: plot_thick_cylinder_implicit.py TABLE.md OUT.png"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

table, out = sys.argv[1], sys.argv[2]
rows = []
for line in open(table):
    cells = [c.strip() for c in line.strip().strip("|").split("|")]
    if len(cells) < 4 or not cells[0][:1].isdigit():
        continue
    rows.append((float(cells[0]), float(cells[1]), cells[2], float(cells[3])))
hs = sorted({r[1] for r in rows}, reverse=True)
fig, ax = plt.subplots(figsize=(7, 5))
colours = {"standard": "C3", "theta-bar": "C0", "node": "C2"}
for variant, colour in colours.items():
    for k, h in enumerate(hs):
        d = sorted((nu, u) for nu, hh, v, u in rows if v == variant and hh == h)
        ax.semilogx([1 / (1 - 2 * nu) for nu, _ in d], [u for _, u in d],
                    ["o-", "s--", "^:"][k % 3], color=colour,
                    label=f"{variant.replace('node', 'node average')}, h = {h}")
nus = sorted({r[0] for r in rows})
ax.set_xticks([1 / (1 - 2 * nu) for nu in nus])
ax.set_xticklabels([f"{nu:g}" for nu in nus])
ax.minorticks_off()
ax.axhline(1, color="k", lw=0.8)
ax.set_xlabel(r"Poisson's ratio $\nu$ (axis: $1/(1-2\nu)$)")
ax.set_ylabel(r"$u_r$(inner) / Lamé")
ax.set_ylim(0.4, 1.1)
ax.legend(loc="lower left")
ax.set_title("thick cylinder, quasi-static, one load step")
fig.tight_layout()
fig.savefig(out, dpi=120)
