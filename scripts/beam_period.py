#!/usr/bin/python3
"""Period of the cantilever from statistics.txt: mean interval between
zero crossings of the tip displacement with the same sign (upward), the
crossing times found by linear interpolation. Prints T and T/T_EB.
Usage: beam_period.py OUTPUT_DIR [L H E rho]"""
import math
import sys

import pandas as pd

out = sys.argv[1]
L, H, E, rho = (float(v) for v in (sys.argv[2:6] if len(sys.argv) > 5
                                   else (1, 0.1, 1e7, 1000)))
d = pd.read_csv(f"{out}/statistics.txt", sep=r"\s+")
t, u = d.time.values, d.tip_displacement_y.values
up = [t[i] - u[i] * (t[i + 1] - t[i]) / (u[i + 1] - u[i])
      for i in range(len(t) - 1) if u[i] < 0 <= u[i + 1]]
if len(up) < 2:
    sys.exit("fewer than two upward zero crossings: run longer")
T = (up[-1] - up[0]) / (len(up) - 1)
omega1 = 3.51602 * math.sqrt(E * H**3 / 12 / (rho * H * L**4))
T_EB = 2 * math.pi / omega1
print(f"T = {T:.5f} s  T/T_EB = {T / T_EB:.4f}  (T_EB = {T_EB:.5f} s, "
      f"{len(up) - 1} periods)")
