#!/usr/bin/python3
"""Self-weight column by the quasi-static integrator, from OUT/table.txt of
scripts/column_implicit_study.sh: the sigma_yy error (RMS over the
particles, divided by rho g l0) against the cell height h for every
shape-function family, small deformation on the left, large (the elastic
column compaction) on the right.
Usage: plot_column_implicit.py OUT OUT.png"""
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

folder, out = sys.argv[1], sys.argv[2]
rows = [l.split() for l in open(os.path.join(folder, "table.txt"))][1:]
families = ["standard", "uGIMP", "cpGIMP", "CPDI", "CPDI2"]
styles = ["o-", "s--", "^:", "D-.", "v-"]
fig, axes = plt.subplots(1, 2, figsize=(10, 4.5), sharey=True)
for ax, deformation, title in zip(
        axes, ["small", "large"],
        ["small deformation (E = 1 GPa)",
         "large deformation (E = 1 MPa, 4% at the base)"]):
    for k, family in enumerate(families):
        d = sorted((float(r[2]), float(r[3])) for r in rows
                   if r[0] == deformation and r[1] == family)
        if d:
            ax.loglog([h for h, _ in d], [e for _, e in d], styles[k],
                      color=f"C{k}", label=family, alpha=0.85)
    hs = sorted({float(r[2]) for r in rows})
    if hs:
        ax.loglog(hs, [0.005 * h for h in hs], "k:", lw=0.8, label="slope 1")
        ax.loglog(hs, [0.0004 * h * h for h in hs], "k--", lw=0.8,
                  label="slope 2")
    ax.set_xlabel("cell height h [m]")
    ax.set_title(title)
    ax.grid(True, which="both", alpha=0.3)
axes[0].set_ylabel(r"RMS($\sigma_{yy}$ error) / $\rho g l_0$")
axes[1].legend(loc="lower right")
fig.suptitle("self-weight column, quasi-static, 20 load steps")
fig.tight_layout()
fig.savefig(out, dpi=120)
