#!/usr/bin/python3
"""A body mesh of the quarter annulus a <= r <= b, 0 <= theta <= pi/2 as a
UCD file: n_radial x n_angular straight-sided quads (nodes on the arcs), and
its boundary faces as UCD "line" cells, whose material id deal.II's
GridIn::read_ucd takes as the face's boundary id:
  1: inner arc r = a (where Traction boundary ids = 1 puts the pressure),
  2: outer arc r = b, 3: the edge y = 0, 4: the edge x = 0.
Cells are numbered with the radial index fastest.
Usage: make_quarter_annulus.py OUT.ucd a b n_radial n_angular"""
import math
import sys

out = sys.argv[1]
a, b = float(sys.argv[2]), float(sys.argv[3])
nr, nt = int(sys.argv[4]), int(sys.argv[5])


def node(i, j):
    return j * (nr + 1) + i + 1


with open(out, "w") as f:
    n_lines = 2 * nt + 2 * nr
    f.write(f"{(nr + 1) * (nt + 1)} {nr * nt + n_lines} 0 0 0\n")
    for j in range(nt + 1):
        t = 0.5 * math.pi * j / nt
        # the straight edges exactly on x = 0 and y = 0 (the slip walls)
        c = 0. if j == nt else math.cos(t)
        s = 0. if j == 0 else math.sin(t)
        for i in range(nr + 1):
            r = a + (b - a) * i / nr
            f.write(f"{node(i, j)} {r * c:.15g} {r * s:.15g} 0\n")
    k = 0
    # counter-clockwise: e_r x e_theta = e_z
    for j in range(nt):
        for i in range(nr):
            k += 1
            f.write(f"{k} 0 quad {node(i, j)} {node(i + 1, j)} "
                    f"{node(i + 1, j + 1)} {node(i, j + 1)}\n")
    for j in range(nt):
        k += 1
        f.write(f"{k} 1 line {node(0, j)} {node(0, j + 1)}\n")
        k += 1
        f.write(f"{k} 2 line {node(nr, j)} {node(nr, j + 1)}\n")
    for i in range(nr):
        k += 1
        f.write(f"{k} 3 line {node(i, 0)} {node(i + 1, 0)}\n")
        k += 1
        f.write(f"{k} 4 line {node(i, nt)} {node(i + 1, nt)}\n")
