#!/usr/bin/python3
"""Hertzian contact (scripts/hertz_contact_study.sh): the nodal contact
pressure F_i / h along the plane against Hertz's p0 sqrt(1 - x^2 / a^2)
for the measured load, and the errors of the half-width and the peak
pressure against a / h, for each number of particles per direction.

    plot_hertz_contact.py RESULTS OUT.png"""
import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

results, out = sys.argv[1], sys.argv[2]
R, E_star, centre = 0.5, 1e7 / (1 - 0.3**2), 0.6
runs = {}
for f in os.listdir(results):
    m = re.fullmatch(r"k(\d+)_ppd(\d+)\.csv", f)
    if m:
        runs[(int(m[1]), int(m[2]))] = f
fig, (left, right) = plt.subplots(1, 2, figsize=(10, 4))
colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
# the pressure profiles, scaled by Hertz's a and p0 for the measured load
for n, (k, ppd) in enumerate(sorted(runs, key=lambda r: (-r[1], r[0]))):
    rows = [l.split(",") for l in open(os.path.join(results, runs[(k, ppd)]))]
    x = [float(r[0]) - centre for r in rows[1:]]
    F = [float(r[3]) for r in rows[1:]]
    h = 0.05 / k
    load = sum(F)
    a = math.sqrt(4 * load * R / (math.pi * E_star))
    p0 = 2 * load / (math.pi * a)
    left.plot([xi / a for xi in x], [Fi / h / p0 for Fi in F],
              "o-" if ppd == 4 else "s--", ms=3, color=colours[n % 10],
              label=f"a = {2 * k} h, {ppd} particles per direction")
s = [i / 200 - 1 for i in range(401)]
left.plot(s, [math.sqrt(max(1 - si * si, 0)) for si in s], "k-", lw=2,
          label="Hertz")
left.set_xlabel("x / a")
left.set_ylabel("nodal contact force / (h p0)")
left.set_xlim(-1.5, 1.5)
left.legend(fontsize=7)
left.set_title("contact pressure at t = 0.25 s")
# the errors against the resolution
for n, ppd in enumerate(sorted({p for _, p in runs}, reverse=True)):
    ks = sorted(k for k, p in runs if p == ppd)
    err = {c: [] for c in ("half_width_error", "peak_pressure_error")}
    for k in ks:
        rows = [l.split() for l in open(os.path.join(
            results, f"k{k}_ppd{ppd}.statistics.txt"))]
        v = dict(zip(rows[0], rows[-1]))
        for c in err:
            err[c].append(100 * float(v[c]))
    right.plot([2 * k for k in ks], err["half_width_error"], "o-",
               color=colours[n], label=f"half-width, {ppd} per direction")
    right.plot([2 * k for k in ks], err["peak_pressure_error"], "s--",
               color=colours[n], label=f"peak pressure, {ppd} per direction")
right.axhspan(-2, 2, color="0.9")
right.axhline(0, color="k", lw=0.5)
right.set_xscale("log", base=2)
ticks = sorted({2 * k for k, _ in runs})
right.set_xticks(ticks)
right.set_xticklabels([str(t) for t in ticks])
right.minorticks_off()
right.set_xlabel("a / h")
right.set_ylabel("error against Hertz [%]")
right.legend(fontsize=7)
right.set_title("under refinement")
fig.tight_layout()
fig.savefig(out, dpi=120)
