#!/usr/bin/python3
"""A graded background grid for the strip footing (prm/strip_footing.prm)
and the soil's body mesh, as UCD files: axis-parallel cells of size h on
the region of the collapse mechanism, [0, 1.75] x [4, 5.5] (B = 1, footing
half width 0.5 at x = 0, soil surface y = 5), growing by at most 1.25 per
cell towards the far walls (x = 5, y = 0) and the grid's top (y = 6.25).
The grid's faces get the boundary ids of a box: 0 at x = 0, 1 at x = 5,
2 at y = 0, 3 at y = 6.25. BODY.ucd holds the grid's cells below y = 5,
so that each soil particle sits in a grid cell as a quadrature point in a
finite element (2 x 2 per cell with Particles per direction = 2).
With H_EDGE (smaller than h) the cells are H_EDGE on
[0.5 - w, 0.5 + w] x [5 - w, 5 + w], w = 8 H_EDGE, around the footing's
edge, where the stress is singular, growing by at most 1.25 to h.
Prints the cell counts. Usage: make_strip_footing_grid.py GRID.ucd
BODY.ucd h [H_EDGE]"""
import math
import sys

import structured_quad_ucd

grid_path, body_path, h = sys.argv[1], sys.argv[2], float(sys.argv[3])
h_edge = float(sys.argv[4]) if len(sys.argv) > 4 else h
ratio = 1.25


def graded(length, h):
    """Cell sizes growing from about h by the factor 1.25 over `length`,
    scaled to sum to it exactly."""
    n = max(1, math.ceil(math.log(1 + length * (ratio - 1) / (h * ratio))
                         / math.log(ratio)))
    sizes = [h * ratio ** (k + 1) for k in range(n)]
    scale = length / sum(sizes)
    return [s * scale for s in sizes]


def uniform(length, h):
    n = round(length / h)
    if abs(n * h - length) > 1e-12 * length:
        sys.exit(f"make_strip_footing_grid.py: h = {h} does not divide {length}")
    return [h] * n


def around(start, point, end):
    """Cells over [start, end]: h_edge within 8 h_edge of `point`, growing
    by 1.25 from there to h, h elsewhere (stretched slightly to fit)."""
    if h_edge >= h:
        return uniform(end - start, h)
    w = 8 * h_edge
    growth = []
    while h_edge * ratio ** (len(growth) + 1) < 0.999 * h:
        growth.append(h_edge * ratio ** (len(growth) + 1))
    before = point - w - sum(growth) - start
    after = end - point - w - sum(growth)
    if before < h or after < h:
        sys.exit("make_strip_footing_grid.py: H_EDGE's zone does not fit")
    fit = lambda length: [length / round(length / h)] * round(length / h)
    return (fit(before) + growth[::-1] + [h_edge] * round(2 * w / h_edge) +
            growth + fit(after))


def coordinates(start, sizes):
    x = [start]
    for s in sizes:
        x.append(x[-1] + s)
    return x


xs = coordinates(0.0, around(0.0, 0.5, 1.75) + graded(3.25, h))
ys = coordinates(0.0, list(reversed(graded(4.0, h))) + around(4.0, 5.0, 5.5) +
                 graded(0.75, h))
xs[-1], ys[-1] = 5.0, 6.25
surface = min(range(len(ys)), key=lambda j: abs(ys[j] - 5.0))
edge = min(range(len(xs)), key=lambda i: abs(xs[i] - 0.5))
assert abs(ys[surface] - 5.0) < 1e-9 and abs(xs[edge] - 0.5) < 1e-9
ys[surface], xs[edge] = 5.0, 0.5
nx, ny = len(xs) - 1, len(ys) - 1


points = [(x, y) for y in ys for x in xs]
structured_quad_ucd.write(grid_path, points, nx, ny, side_ids=(0, 1, 2, 3))
structured_quad_ucd.write(body_path, points, nx, surface)
print(f"grid {nx} x {ny} cells, soil {nx} x {surface}, smallest {h_edge:g}, "
      f"largest {max(max(b - a for a, b in zip(xs, xs[1:])), max(b - a for a, b in zip(ys, ys[1:]))):.3f}")
