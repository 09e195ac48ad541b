#!/usr/bin/python3
"""Cantilever plots from scripts/cantilever_study.sh output: the period
over the FE reference period T_FE against the cells through the depth (2x2
particles per cell) for standard MPM and the filter with both metrics, and
the tip displacement over time at 2 cells.
Usage: plot_cantilever.py STUDY_DIR OUT.png"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

study, out = sys.argv[1], sys.argv[2]
t = pd.read_csv(f"{study}/table.txt", sep=r"\s+")
fig, (a, b) = plt.subplots(1, 2, figsize=(12, 4.5))
for variant, d in t[t.ppc == 2].groupby("variant"):
    a.plot(d.cells, d["T/T_FE"], "o-", label=variant)
for ppc, d in t[(t.variant == "standard") & (t.ppc > 2)].groupby("ppc"):
    a.plot(d.cells, d["T/T_FE"], "x:", label=f"standard, {ppc}x{ppc} ppc")
a.axhspan(0.99, 1.01, color="0.9", label="within 1%")
a.axhline(1, color="k", lw=0.8)
a.set_xscale("log", base=2)
a.set_xticks([1, 2, 4], ["1", "2", "4"])
a.set_xlabel("cells through the depth")
a.set_ylabel("T / T_FE (FE reference, mpm-fe)")
a.set_title("period (2x2 particles per cell unless noted)")
a.legend(fontsize=8)
for variant in ["standard", "filter-mass", "filter-compliance"]:
    s = pd.read_csv(f"{study}/2_2_{variant}/statistics.txt", sep=r"\s+")
    b.plot(s.time, s.tip_displacement_y * 1e3, label=variant)
b.set_xlabel("t [s]")
b.set_ylabel("tip displacement [mm]")
b.set_title("2 cells through the depth")
b.legend(fontsize=8)
fig.suptitle("Vibrating cantilever, L/H = 10, plane stress (scripts/cantilever_study.sh)")
fig.tight_layout()
fig.savefig(out, dpi=110)
print(f"wrote {out}")
