#!/usr/bin/python3
"""A distorted quadrilateral background grid of the box [0,W]x[0,Ht] as a
UCD file: nx x ny cells, every node moved by a reproducible pseudo-random
offset of at most `amount` times the cell size, nodes on the box edges
only along their edge (so slip walls stay straight). All boundary faces get
id 0. Usage: make_distorted_grid.py OUT.ucd W Ht nx ny [amount] [seed]"""
import random
import sys

out = sys.argv[1]
W, Ht = float(sys.argv[2]), float(sys.argv[3])
nx, ny = int(sys.argv[4]), int(sys.argv[5])
amount = float(sys.argv[6]) if len(sys.argv) > 6 else 0.2
rng = random.Random(int(sys.argv[7]) if len(sys.argv) > 7 else 1)
hx, hy = W / nx, Ht / ny
nodes = []
for j in range(ny + 1):
    for i in range(nx + 1):
        dx = rng.uniform(-amount, amount) * hx
        dy = rng.uniform(-amount, amount) * hy
        if i in (0, nx):
            dx = 0
        if j in (0, ny):
            dy = 0
        nodes.append((i * hx + dx, j * hy + dy))
with open(out, "w") as f:
    f.write(f"{len(nodes)} {nx * ny} 0 0 0\n")
    for k, (x, y) in enumerate(nodes):
        f.write(f"{k + 1} {x:.12f} {y:.12f} 0\n")
    c = 0
    for j in range(ny):
        for i in range(nx):
            c += 1
            a = j * (nx + 1) + i + 1
            f.write(f"{c} 0 quad {a} {a + 1} {a + nx + 2} {a + nx + 1}\n")
