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

import structured_quad_ucd

out = sys.argv[1]
a, b = float(sys.argv[2]), float(sys.argv[3])
nr, nt = int(sys.argv[4]), int(sys.argv[5])


points = []
for j in range(nt + 1):
    t = 0.5 * math.pi * j / nt
    # the straight edges exactly on x = 0 and y = 0 (the slip walls)
    c = 0. if j == nt else math.cos(t)
    s = 0. if j == 0 else math.sin(t)
    for i in range(nr + 1):
        r = a + (b - a) * i / nr
        points.append((r * c, r * s))
# i along r, j along theta: counter-clockwise, e_r x e_theta = e_z
structured_quad_ucd.write(out, points, nr, nt, side_ids=(1, 2, 3, 4))
