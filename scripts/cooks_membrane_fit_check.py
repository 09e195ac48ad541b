#!/usr/bin/python3
"""How much the point measure of Benchmark = cooks membrane depends on the
fit: from the final particles of each run of scripts/cooks_membrane_study.sh,
u_y(48,60) over the FE reference by the least-squares plane through the
particles within r of the corner for r = h/2, h (the benchmark's choice),
2h, by a quadratic fit within 2h, and the particle nearest the corner.
Usage: cooks_membrane_fit_check.py STUDY_DIR"""
import glob
import os
import sys

import numpy as np
import pandas as pd

study = sys.argv[1]
reference = {"a": 1e-3 * 25.19, "b": 0.07771}  # F uy_ref of the prm files
X0 = np.array([48.0, 60.0])


def fit(d, r, quadratic=False):
    dx, dy = d.X_x.values - X0[0], d.X_y.values - X0[1]
    near = np.hypot(dx, dy) <= r
    cols = [np.ones(near.sum()), dx[near], dy[near]]
    if quadratic:
        cols += [dx[near] ** 2, dx[near] * dy[near], dy[near] ** 2]
    A = np.stack(cols, axis=1)
    if near.sum() < A.shape[1] or np.linalg.matrix_rank(A) < A.shape[1]:
        return np.nan
    uy = (d.y - d.X_y).values[near]
    return np.linalg.lstsq(A, uy, rcond=None)[0][0]


print(f"{'run':28s} {'r=h/2':>8s} {'r=h':>8s} {'r=2h':>8s} "
      f"{'quad 2h':>8s} {'nearest':>8s}")
for run in sorted(glob.glob(f"{study}/[ab]_*_*/")):
    name = os.path.basename(run.rstrip("/"))
    case, h = name.split("_")[0], float(name.split("_")[1])
    files = sorted(glob.glob(f"{run}/particles-*.csv"))
    if not files:
        continue
    d = pd.read_csv(files[-1])
    ref = reference[case]
    r = np.hypot(d.X_x - X0[0], d.X_y - X0[1])
    nearest = (d.y - d.X_y).values[np.argmin(r.values)]
    values = [fit(d, h / 2), fit(d, h), fit(d, 2 * h),
              fit(d, 2 * h, True), nearest]
    print(f"{name:28s} " + " ".join(f"{v / ref:8.4f}" for v in values))
