#!/usr/bin/python3
"""The cantilever by the Newmark integrator, from the table of
scripts/cantilever_newmark_study.sh: left, the period over T_FE against
the cells through the depth for standard MPM and the two filter metrics
(step 0.01 s); right, the compliance filter's period at 2 cells against
the step over the explicit stability limit, with the trapezoidal rule's
period elongation (omega dt)^2 / 12 added to the smallest step's value.
Usage: plot_cantilever_newmark.py TABLE.txt OUT.png"""
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

d = pd.read_csv(sys.argv[1], sep=r"\s+")
fig, (left, right) = plt.subplots(1, 2, figsize=(11, 4.5))
base = d[d.dt == 0.01]
for k, (variant, marker) in enumerate([("standard", "o-"),
                                       ("filter-mass", "s--"),
                                       ("filter-compliance", "^-")]):
    r = base[base.variant == variant].sort_values("cells")
    left.plot(r.cells, r.T_over_T_FE, marker, color=f"C{k}", label=variant)
left.axhline(1, color="k", lw=0.8)
left.axhspan(0.99, 1.01, color="0.9", zorder=0, label="within 1%")
left.set_xscale("log", base=2)
left.set_xticks([1, 2, 4])
left.set_xticklabels(["1", "2", "4"])
left.set_xlabel("cells through the depth (step 0.01 s)")
left.set_ylabel(r"$T / T_{FE}$")
left.legend()
left.set_title("Newmark, period against the grid")

r = d[(d.cells == 2) & (d.variant == "filter-compliance")].sort_values("dt")
right.plot(r.dt_over_limit, r.T_over_T_FE, "^-", color="C2",
           label="filter, compliance, 2 cells")
T0, dt0 = r.T_over_T_FE.iloc[0], r.dt.iloc[0]
omega = 2 * math.pi / 0.62322
dts = r.dt.values
right.plot(r.dt_over_limit,
           [T0 * (1 + (omega * x) ** 2 / 12) / (1 + (omega * dt0) ** 2 / 12)
            for x in dts], "k:", label=r"$+(\omega\,\Delta t)^2/12$")
right.axhline(1, color="k", lw=0.8)
right.axvline(20, color="0.5", lw=0.8, ls="--")
right.set_xscale("log")
right.set_xlabel(r"$\Delta t$ / explicit stability limit")
right.set_ylabel(r"$T / T_{FE}$")
right.legend()
right.set_title("Newmark, period against the step")
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=120)
