#!/usr/bin/env python3
"""The settled water in the glass (doc/benchmarks/glass_pour.md), from the
last particle table and the statistics file of each run folder given:

- mass: injected mass, particle mass + removed mass, their difference;
- depth: the water surface above the glass's base, from the particles'
  positions (mean over the grid columns inside the glass of the top
  particle's height plus half its size);
- level: the depth the particles' volume gives (their volume inside the
  glass over the glass's inner section), and the depth the injected
  volume gives;
- bottom pressure: the volume-weighted mean pressure of the particles in
  the first cell layer above the base, against rho g (depth - y) at their
  mean height y;
- checkerboard: RMS over face-neighbouring cells inside the glass of the
  jump of the cell's volume-averaged p + rho g y, over rho g depth (the
  water column's measure);
- surface: the spread (max - min) of the column tops, in cells;
- the largest particle speed.

The glass is that of prm/glass/glass_*.geo with its defaults.

usage: glass_pour_measures.py RUN_DIR [RUN_DIR ...]
"""
import glob
import os
import sys

import numpy as np

RHO, G = 1000.0, 9.81
CENTRE, RI, BASE = 0.08, 0.0325, 0.005  # the .geo files' defaults
H = {2: 0.0025, 3: 0.005}  # their cell sizes


def last_row(statistics):
    with open(statistics) as f:
        header = f.readline().split()
        rows = [line.split() for line in f if line.strip()]
    return dict(zip(header, map(float, rows[-1])))


def measures(run):
    tables = sorted(glob.glob(os.path.join(run, "particles-*.csv")))
    d = np.genfromtxt(tables[-1], delimiter=",", names=True)
    dim = 3 if "z" in d.dtype.names else 2
    h = H[dim]
    up = "z" if dim == 3 else "y"
    across = ["x", "y"] if dim == 3 else ["x"]
    height = d[up]
    inside = height > BASE
    for c in across:
        inside &= np.abs(d[c] - CENTRE) < RI
    section = (2 * RI) ** (dim - 1)
    pressure = -(d["stress_xx"] + d["stress_yy"] + d["stress_zz"]) / 3
    volume = d["volume"]
    size = volume ** (1.0 / dim)

    # columns and cells of the grid inside the glass (cell-aligned there)
    col = [np.floor((d[c] - (CENTRE - RI)) / h).astype(int) for c in across]
    row = np.floor((height - BASE) / h).astype(int)
    tops = {}
    cells = {}
    for p in np.where(inside)[0]:
        key = tuple(c[p] for c in col)
        tops[key] = max(tops.get(key, -1), height[p] + size[p] / 2)
        cells.setdefault(key + (row[p],), []).append(p)
    top = np.array(list(tops.values()))
    depth = top.mean() - BASE
    average = {}
    for key, ps in cells.items():
        w = volume[ps]
        average[key] = (np.dot(w, pressure[ps]) / w.sum(),
                        np.dot(w, height[ps]) / w.sum())
    bottom = [k for k in average if k[-1] == 0]
    p_bottom = np.mean([average[k][0] for k in bottom])
    y_bottom = np.mean([average[k][1] for k in bottom])
    hydrostatic = RHO * G * (BASE + depth - y_bottom)
    jumps = []
    for key, (p, y) in average.items():
        for axis in range(dim):
            other = list(key)
            other[axis] += 1
            other = tuple(other)
            if other in average:
                q, z = average[other]
                jumps.append((p + RHO * G * y) - (q + RHO * G * z))
    stats = last_row(os.path.join(run, "statistics.txt"))
    injected = stats.get("injected_mass", float("nan"))
    speed = np.sqrt(sum(d["v_" + c] ** 2 for c in ["x", "y", "z"][:dim]))
    return {
        "run": run.rstrip("/"),
        "t": stats["time"],
        "injected": injected,
        "mass_error": stats["mass"] + stats["removed_mass"] - injected,
        "removed": stats["removed_mass"],
        "depth": depth,
        "level_volume": volume[inside].sum() / section,
        "level_injected": injected / RHO / section,
        "p_bottom": p_bottom,
        "p_error": p_bottom / hydrostatic - 1,
        "checkerboard": np.sqrt(np.mean(np.square(jumps))) / (RHO * G * depth),
        "surface": (top.max() - top.min()) / h,
        "fill": np.mean([len(cells[k]) for k in bottom]) / 2**dim,
        "max_speed": speed.max(),
    }


def main(runs):
    print("| run | t [s] | injected [kg] | mass + removed - injected | removed "
          "| depth [mm] | level from volume [mm] | level from injected [mm] "
          "| bottom p [Pa] | vs rho g (depth - y) | checkerboard "
          "| surface spread [cells] | bottom fill | max speed [m/s] |")
    print("|" + "---|" * 14)
    for run in runs:
        m = measures(run)
        print(f"| {os.path.basename(m['run'])} | {m['t']:.2f} "
              f"| {m['injected']:.6g} | {m['mass_error']:.1e} "
              f"| {m['removed']:.3g} | {1e3 * m['depth']:.1f} "
              f"| {1e3 * m['level_volume']:.1f} "
              f"| {1e3 * m['level_injected']:.1f} | {m['p_bottom']:.0f} "
              f"| {100 * m['p_error']:+.1f}% | {m['checkerboard']:.3f} "
              f"| {m['surface']:.1f} | {m['fill']:.2f} "
              f"| {m['max_speed']:.3f} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
