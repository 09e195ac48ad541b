#!/usr/bin/python3
"""A distorted quadrilateral background grid of the box [0,W]x[0,Ht] as a
UCD file: nx x ny cells, every node moved by a reproducible pseudo-random
offset of at most `amount` times the cell size, nodes on the box edges
only along their edge (so slip walls stay straight). All boundary faces get
id 0. Usage: make_distorted_grid.py OUT.ucd W Ht nx ny [amount] [seed]
                               [BODY.ucd Hb]
With BODY.ucd and Hb (a multiple of Ht/ny): the nodes on y = Hb stay on
that line too, and the cells below it are written to BODY.ucd as well, a
body mesh that conforms to the grid (particles then sit in the grid cells
as quadrature points sit in finite elements)."""
import random
import sys

import structured_quad_ucd

out = sys.argv[1]
W, Ht = float(sys.argv[2]), float(sys.argv[3])
nx, ny = int(sys.argv[4]), int(sys.argv[5])
amount = float(sys.argv[6]) if len(sys.argv) > 6 else 0.2
rng = random.Random(int(sys.argv[7]) if len(sys.argv) > 7 else 1)
body = sys.argv[8] if len(sys.argv) > 9 else None
jb = round(float(sys.argv[9]) / (Ht / ny)) if body else None
hx, hy = W / nx, Ht / ny
nodes = []
for j in range(ny + 1):
    for i in range(nx + 1):
        dx = rng.uniform(-amount, amount) * hx
        dy = rng.uniform(-amount, amount) * hy
        if i in (0, nx):
            dx = 0
        if j in (0, ny) or j == jb:
            dy = 0
        nodes.append((i * hx + dx, j * hy + dy))


structured_quad_ucd.write(out, nodes, nx, ny, number="{:.12f}")
if body:
    structured_quad_ucd.write(body, nodes, nx, jb, number="{:.12f}")
