#!/usr/bin/env python3
"""Pictures of the pour into the glass (doc/benchmarks/glass_pour.md),
headless, from the particle tables of the runs:

  plot_glass_pour.py snapshots OUT.png TIMES RUN_DIR [RUN_DIR ...]
      the particles coloured by pressure, one row per run (standard MPM
      beside the remedies), one column per time (TIMES: "0.2,0.4,2.5")
  plot_glass_pour.py frame OUT.png TIME RUN_DIR
      one picture at TIME (3D: the particles in perspective, the glass
      drawn in outline)
  plot_glass_pour.py animation OUT.gif RUN_DIR
      every output of the run, 10 frames per second

The glass is that of prm/glass/glass_*.geo with its defaults.
"""
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.animation import FuncAnimation, PillowWriter  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

RHO, G = 1000.0, 9.81
W, HEIGHT, CENTRE, RI, TB, HG = 0.16, 0.16, 0.08, 0.0325, 0.005, 0.1
WALL = {2: 0.0025, 3: 0.005}
P_MAX = RHO * G * 0.08  # colour scale: a little above the settled bottom


def outputs(run):
    """(time, particle table) of every output of the run."""
    with open(os.path.join(run, "statistics.txt")) as f:
        f.readline()
        times = [float(line.split()[0]) for line in f if line.strip()]
    tables = sorted(glob.glob(os.path.join(run, "particles-*.csv")))
    return list(zip(times, tables))


def table_at(run, t):
    return min(outputs(run), key=lambda o: abs(o[0] - t))


def load(table):
    d = np.genfromtxt(table, delimiter=",", names=True)
    p = -(d["stress_xx"] + d["stress_yy"] + d["stress_zz"]) / 3
    return d, p


def draw_2d(ax, table, title):
    d, p = load(table)
    t = WALL[2]
    for x0, y0, w, h in [(CENTRE - RI - t, 0, t, HG), (CENTRE + RI, 0, t, HG),
                         (CENTRE - RI, 0, 2 * RI, TB)]:
        ax.add_patch(Rectangle((x0, y0), w, h, color="0.55"))
    ax.plot([0, W], [0, 0], color="0.3", lw=2)
    s = ax.scatter(d["x"], d["y"], c=p, s=2, cmap="viridis", vmin=0,
                   vmax=P_MAX, linewidths=0)
    ax.set_xlim(0.02, W - 0.02)
    ax.set_ylim(-0.003, 0.15)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(title, fontsize=9)
    return s


def glass_edges_3d(ax):
    t = WALL[3]
    for r, z0, z1 in [(RI + t, 0, HG), (RI, TB, HG)]:
        corners = [(-r, -r), (r, -r), (r, r), (-r, r), (-r, -r)]
        for z in (z0, z1):
            ax.plot([CENTRE + a for a, _ in corners],
                    [CENTRE + b for _, b in corners], [z] * 5,
                    color="0.35", lw=0.8)
        for a, b in corners[:4]:
            ax.plot([CENTRE + a] * 2, [CENTRE + b] * 2, [z0, z1],
                    color="0.35", lw=0.8)


def draw_3d(ax, table, title):
    d, p = load(table)
    # the near half cut away, so the inside of the glass shows
    keep = d["y"] >= CENTRE - 0.0025
    glass_edges_3d(ax)
    s = ax.scatter(d["x"][keep], d["y"][keep], d["z"][keep], c=p[keep], s=1,
                   cmap="viridis", vmin=0, vmax=P_MAX, depthshade=False)
    ax.set_xlim(CENTRE - 0.045, CENTRE + 0.045)
    ax.set_ylim(CENTRE - 0.045, CENTRE + 0.045)
    ax.set_zlim(-0.005, 0.15)
    ax.set_box_aspect((0.09, 0.09, 0.155), zoom=1.2)
    ax.view_init(elev=18, azim=-60)
    ax.set_axis_off()
    ax.set_title(title, fontsize=9)
    return s


def dimension(table):
    with open(table) as f:
        return 3 if "z" in f.readline().split(",") else 2


def figure_for(dim, rows=1, cols=1, size=3.0):
    kw = {"projection": "3d"} if dim == 3 else {}
    fig, axes = plt.subplots(rows, cols, figsize=(size * cols, size * rows),
                             subplot_kw=kw, squeeze=False)
    return fig, axes


def snapshots(out, times, runs):
    times = [float(t) for t in times.split(",")]
    dim = dimension(outputs(runs[0])[0][1])
    fig, axes = figure_for(dim, len(runs), len(times), 2.6 if dim == 2 else 3.2)
    for i, run in enumerate(runs):
        for j, t in enumerate(times):
            time, table = table_at(run, t)
            draw = draw_3d if dim == 3 else draw_2d
            s = draw(axes[i][j], table,
                     f"{os.path.basename(run.rstrip('/'))}, t = {time:.2f} s")
    fig.colorbar(s, ax=axes, shrink=0.6, label="pressure [Pa]")
    fig.savefig(out, dpi=130)


def frame(out, t, run):
    time, table = table_at(run, float(t))
    dim = dimension(table)
    fig, axes = figure_for(dim, size=5)
    draw = draw_3d if dim == 3 else draw_2d
    s = draw(axes[0][0], table, f"t = {time:.2f} s")
    fig.colorbar(s, ax=axes, shrink=0.6, label="pressure [Pa]")
    fig.savefig(out, dpi=130)


def animation(out, run):
    series = outputs(run)
    dim = dimension(series[0][1])
    fig, axes = figure_for(dim, size=4)
    ax = axes[0][0]
    draw = draw_3d if dim == 3 else draw_2d

    def show(i):
        ax.clear()
        draw(ax, series[i][1], f"t = {series[i][0]:.2f} s")

    FuncAnimation(fig, show, frames=len(series)).save(
        out, writer=PillowWriter(fps=10), dpi=90)


if __name__ == "__main__":
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    what, out, rest = sys.argv[1], sys.argv[2], sys.argv[3:]
    if what == "snapshots":
        snapshots(out, rest[0], rest[1:])
    elif what == "frame":
        frame(out, rest[0], rest[1])
    elif what == "animation":
        animation(out, rest[0])
    else:
        sys.exit(__doc__)
