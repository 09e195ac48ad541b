#!/usr/bin/python3
"""Recompute a benchmark's error measures from the particle CSV files of a
run and compare them with the benchmark columns of its statistics.txt.

    recompute_measures.py OUTPUT_DIR [--benchmark NAME] [--prm FILE] [--all]

OUTPUT_DIR is a run's Output/Directory with statistics.txt and
particles-NNNNN.csv (Output/Write csv = true). particles-NNNNN.csv holds
the particles of statistics row NNNNN (both are written at every output),
so every CSV present is compared with its row; missing CSVs (a study that
deleted some) are skipped. The benchmark, its constants and the grid come
from OUTPUT_DIR/parameters.prm, which mpm writes at the start of a run
(--prm reads a parameter file instead, with its `include` lines expanded;
--benchmark overrides the name).

The measures are those of source/benchmarks/*.cc, written out again here
with numpy (the formulas are repeated in the functions below):
  axial bar             v_cm, v_cm_exact, v_rms_error
  convecting bar        sigma_rms_error, v_rms_error
  cantilever            tip_displacement_y, and the period from it as
                        scripts/beam_period.py takes it from the statistics
  spinning disk         sigma_rr_rms_error, sigma_rt_rms, v_r_rms
  self-weight column    sigma_yy_error, pressure_error, checkerboard
  thick cylinder        ur_inner_ratio, pressure_error, sigma_rr_error,
                        checkerboard
  manufactured solution u_L2_error, u_max_error

Tolerance. The CSV prints 10 significant digits, so each value v read from
it is off by at most 5e-10 |v|. Each measure is computed together with a
bound on how far that rounding can move it (the rounding of each input
carried through the formula to first order: a weighted RMS or mean moves
by at most the weighted RMS or mean of the moves of its terms, a maximum
by the largest move; a checkerboard, a difference of cell averages, also
by 1e-12 of the largest average for the round-off of the sums). A row
agrees when
    |csv - statistics| <= 2 bound + 1e-9 |statistics|
(the second term covers the rounding of the weights, the 12 digits of the
statistics file and the order of the sums). The exit status is 1 if any
row disagrees, 2 if nothing could be compared.

Not recomputable from the CSV: the checkerboard measures on a mesh-file
background grid (the CSV has positions, not cells; on a box grid the cell
is found from the position). Particles within rounding distance of a cell
face on a box grid are counted and reported: the program may hold them in
either cell.
"""
import argparse
import glob
import math
import os
import re
import sys

import numpy as np
import pandas as pd

ROUND = 5e-10  # relative rounding of a value printed with 10 digits


def u(v):
    """Bound of the rounding of CSV values v."""
    return ROUND * np.abs(v)


# ------------------------------------------------------------ parameters
def read_prm(path, seen=0):
    """Entries 'Subsection/.../Name' -> value of a parameter file, with
    `include` lines expanded (next to the including file, as mpm does) and
    backslash continuations joined."""
    if seen > 20:
        sys.exit(f"{path}: includes nested too deep")
    text = open(path).read().replace("\\\n", " ")
    entries, section = {}, []
    for line in text.splitlines():
        line = line.split("#", 1)[0].strip()
        if not line:
            continue
        if line.startswith("include "):
            name = os.path.join(os.path.dirname(path), line[8:].strip())
            entries.update(read_prm(name, seen + 1))
        elif line.startswith("subsection "):
            section.append(line[11:].strip())
        elif line == "end":
            section.pop()
        elif line.startswith("set "):
            name, value = line[4:].split("=", 1)
            entries["/".join(section + [" ".join(name.split())])] = " ".join(value.split())
    return entries


def constants(entries):
    c = {}
    for item in entries.get("Constants", "").split(","):
        if "=" in item:
            k, v = item.split("=", 1)
            c[k.strip()] = float(eval(v.strip(), {"pi": math.pi}))
    return c


def need(c, *names):
    missing = [n for n in names if n not in c]
    if missing:
        sys.exit(f"the constants {missing} are missing from 'set Constants'")
    return [c[n] for n in names]


def box_grid(entries, dim):
    """(lower, h, n) of a hyper-rectangle grid, or None for a mesh file."""
    if entries.get("Grid/Type", "hyper rectangle") != "hyper rectangle":
        return None
    lo = np.array([float(v) for v in entries["Grid/Lower corner"].split(",")])
    hi = np.array([float(v) for v in entries["Grid/Upper corner"].split(",")])
    n = [int(v) for v in entries.get("Grid/Subdivisions", "10").split(",")]
    n = np.array(n * dim if len(n) == 1 else n) * 2 ** int(entries.get("Grid/Global refinements", "0"))
    return lo, (hi - lo) / n, n


# -------------------------------------------------------------- helpers
def wrms(w, e, de):
    """sqrt(sum w e^2 / sum w) and the bound of its change when each e
    moves by at most de (triangle inequality of the weighted norm)."""
    return np.sqrt((w * e * e).sum() / w.sum()), np.sqrt((w * de * de).sum() / w.sum())


def wmean(w, e, de):
    return (w * e).sum() / w.sum(), (w * de).sum() / w.sum()


def cell_averages(p, dim, grid, error, derror):
    """The volume-averaged error of each cell of a box grid (nan where no
    particle is), its rounding bound, whether the cell has particles (all
    shaped as the grid, x first) and the number of particles on a cell
    face (whose cell is ambiguous)."""
    lo, h, n = grid
    axes = "xyz"[:dim]
    idx, on_face = [], np.zeros(len(p), bool)
    for d, a in enumerate(axes):
        s = (p[a].values - lo[d]) / h[d]
        i = np.clip(np.floor(s).astype(int), 0, n[d] - 1)
        on_face |= np.abs(s - np.rint(s)) < 4 * ROUND * (np.abs(p[a].values) + abs(lo[d])) / h[d] + 1e-12
        idx.append(i)
    cell = np.ravel_multi_index(idx, n)
    V = p.volume.values
    ncell = int(np.prod(n))
    sv = np.bincount(cell, V, ncell)
    se = np.bincount(cell, V * error, ncell)
    sd = np.bincount(cell, V * derror, ncell)
    has = sv > 0
    e = np.where(has, se / np.where(has, sv, 1), np.nan)
    de = np.where(has, sd / np.where(has, sv, 1), np.nan)
    e, de, has = (x.reshape(n) for x in (e, de, has))
    return e, de, has, int(on_face.sum())


def checkerboard(p, dim, grid, error, derror):
    """RMS over face-neighbouring cell pairs with particles of the jump of
    the volume-averaged error (source/benchmarks/checkerboard.cc), its
    rounding bound, and the number of particles on a cell face."""
    e, de, has, on_face = cell_averages(p, dim, grid, error, derror)
    jumps, bounds = [], []
    for d in range(dim):
        a = [slice(None)] * dim
        b = [slice(None)] * dim
        a[d], b[d] = slice(0, -1), slice(1, None)
        both = has[tuple(a)] & has[tuple(b)]
        jumps.append((e[tuple(a)] - e[tuple(b)])[both])
        bounds.append((de[tuple(a)] + de[tuple(b)])[both])
    j, bj = np.concatenate(jumps), np.concatenate(bounds)
    if len(j) == 0:
        return 0.0, 0.0, on_face
    # plus the round-off of the cell averages (a difference of two of them)
    roundoff = 1e-12 * np.nanmax(np.abs(e))
    return np.sqrt((j * j).mean()), np.sqrt((bj * bj).mean()) + roundoff, on_face


def polar(x, y, px, py):
    """cos, sin of the direction (x, y), their rounding-induced angle
    bound from the rounding px, py of x and y, and the radius."""
    r = np.hypot(x, y)
    safe = np.where(r > 0, r, 1)
    c = np.where(r > 0, x / safe, 1.0)
    s = np.where(r > 0, y / safe, 0.0)
    dtheta = np.minimum((px + py) / safe, 2.0)
    return c, s, dtheta, r


# ------------------------------------------------------------- measures
# Each takes the particle table p, the time t and the run's data, and
# returns {column: (value, rounding bound)}.
def axial_bar(p, t, run):
    L, E, rho, v0 = need(run.c, "L", "E", "rho", "v0")
    x0 = run.c.get("x0", 0.0)
    beta = math.pi / (2 * L)
    omega = beta * math.sqrt(E / rho)
    m, X, v = p.mass.values, p.X_x.values - x0, p.v_x.values
    ve = v0 * math.cos(omega * t) * np.sin(beta * X)
    vcm = wmean(m, v, u(v))
    rms, drms = wrms(m, v - ve, u(v) + abs(v0) * beta * u(p.X_x.values))
    return {"v_cm": vcm, "v_cm_exact": (v0 * math.cos(omega * t) / (beta * L), 0.0),
            "v_rms_error": (rms / v0, drms / abs(v0))}


def convecting_bar(p, t, run):
    L, A, b0, v0, x0 = need(run.c, "L", "A", "b0", "v0", "x0")
    sigma0 = b0 * L / (math.pi * A)
    m, X = p.mass.values, p.X_x.values
    s, v = p.stress_xx.values, p.v_x.values
    ds = s + sigma0 * np.sin(math.pi * (X - x0) / L)
    es, des = wrms(m, ds, u(s) + sigma0 * math.pi / L * u(X))
    ev, dev = wrms(m, v - v0, u(v))
    vs = abs(v0) if v0 != 0 else 1.0
    return {"sigma_rms_error": (es / sigma0, des / sigma0),
            "v_rms_error": (ev / vs, dev / vs)}


def cantilever(p, t, run):
    L, H = need(run.c, "L", "H")
    tip = p[p.X_x.values > L - H / 2]
    if len(tip) == 0:
        return {"tip_displacement_y": (0.0, 0.0)}
    d = tip.y.values - tip.X_y.values
    return {"tip_displacement_y": wmean(tip.mass.values, d, u(tip.y.values) + u(tip.X_y.values))}


def spinning_disk(p, t, run):
    a, omega, nu, rho = need(run.c, "a", "omega", "nu", "rho")
    sigma0 = rho * omega**2 * (3 + nu) * a * a / 8
    x, y = p.x.values, p.y.values
    c, s, dth, r = polar(x, y, u(x), u(y))
    sxx, syy, sxy = p.stress_xx.values, p.stress_yy.values, p.stress_xy.values
    smax = np.abs(sxx) + np.abs(syy) + 2 * np.abs(sxy)
    srr = c * c * sxx + s * s * syy + 2 * c * s * sxy
    srt = (syy - sxx) * c * s + (c * c - s * s) * sxy
    dstress = u(sxx) + u(syy) + 2 * u(sxy) + 2 * smax * dth
    exact = rho * omega**2 / 8 * (3 + nu) * (a * a - r * r)
    dexact = rho * omega**2 / 8 * (3 + nu) * 2 * r * (u(x) + u(y))
    vx, vy = p.v_x.values, p.v_y.values
    vr = c * vx + s * vy
    dvr = u(vx) + u(vy) + np.hypot(vx, vy) * dth
    m = p.mass.values
    e1 = wrms(m, srr - exact, dstress + dexact)
    e2 = wrms(m, srt, dstress)
    e3 = wrms(m, vr, dvr)
    return {"sigma_rr_rms_error": (e1[0] / sigma0, e1[1] / sigma0),
            "sigma_rt_rms": (e2[0] / sigma0, e2[1] / sigma0),
            "v_r_rms": (e3[0] / (omega * a), e3[1] / (omega * a))}


def pressure(p):
    s = [p[f"stress_{c}"].values for c in ("xx", "yy", "zz")]
    return -(s[0] + s[1] + s[2]) / 3, (u(s[0]) + u(s[1]) + u(s[2])) / 3


def self_weight_column(p, t, run):
    H, rho, g, nu = need(run.c, "H", "rho", "g", "nu")
    Y = p.X_y.values
    yy = -rho * g * (H - Y)
    xx = nu / (1 - nu) * yy
    zz = nu * (xx + yy) if run.dim == 2 else xx
    dY = rho * g * u(Y) * 2  # |d p_exact/dY|, |d yy/dY| <= 2 rho g
    pm, dpm = pressure(p)
    perr = pm + (xx + yy + zz) / 3
    dperr = dpm + dY
    V = p.volume.values
    scale = rho * g * H
    eyy = wmean(V, np.abs(p.stress_yy.values - yy), u(p.stress_yy.values) + dY)
    ep = wmean(V, np.abs(perr), dperr)
    out = {"sigma_yy_error": (eyy[0] / scale, eyy[1] / scale),
           "pressure_error": (ep[0] / scale, ep[1] / scale)}
    if run.grid is not None:
        cb, dcb, run.on_face = checkerboard(p, run.dim, run.grid, perr, dperr)
        out["checkerboard"] = (cb / scale, dcb / scale)
    return out


def thick_cylinder(p, t, run):
    a, b, pin, E, nu = need(run.c, "a", "b", "p", "E", "nu")
    k = pin * a * a / (b * b - a * a)
    X, Y = p.X_x.values, p.X_y.values
    c, s, dth, R = polar(X, Y, u(X), u(Y))
    pm, dpm = pressure(p)
    perr = pm + (1 + nu) * 2 * k / 3
    sxx, syy, sxy = p.stress_xx.values, p.stress_yy.values, p.stress_xy.values
    srr = c * c * sxx + s * s * syy + 2 * c * s * sxy
    dsrr = (u(sxx) + u(syy) + 2 * u(sxy) + 2 * (np.abs(sxx) + np.abs(syy) + 2 * np.abs(sxy)) * dth
            + 2 * abs(k) * b * b / R**3 * (u(X) + u(Y)))
    V = p.volume.values
    ep = wmean(V, np.abs(perr), dpm)
    er = wmean(V, np.abs(srr - k * (1 - b * b / (R * R))), dsrr)
    inner = R < a + (b - a) / 8
    x, y = p.x.values[inner], p.y.values[inner]
    ci, si, Ri = c[inner], s[inner], R[inner]
    ur = ci * (x - X[inner]) + si * (y - Y[inner])
    dur = u(x) + u(y) + u(X[inner]) + u(Y[inner]) + np.hypot(x - X[inner], y - Y[inner]) * dth[inner]
    m = p.mass.values[inner]
    num, den = (m * ur).sum(), (m * (1 + nu) * k / E * ((1 - 2 * nu) * Ri + b * b / Ri)).sum()
    ratio = (num / den, (m * dur).sum() / abs(den)) if den != 0 else (math.nan, 0.0)
    out = {"ur_inner_ratio": ratio, "pressure_error": (ep[0] / pin, ep[1] / pin),
           "sigma_rr_error": (er[0] / pin, er[1] / pin)}
    if run.grid is not None:
        cb, dcb, run.on_face = checkerboard(p, run.dim, run.grid, perr, dpm)
        out["checkerboard"] = (cb / pin, dcb / pin)
    return out


def manufactured_solution(p, t, run):
    G, E, rho = need(run.c, "G", "E", "rho")
    c = math.sqrt(E / rho)
    e2 = np.zeros(len(p))
    de2 = np.zeros(len(p))
    for d, axis in enumerate("xyz"[: run.dim]):
        X, x = p[f"X_{axis}"].values, p[axis].values
        ud = G * np.sin(math.pi * X) * math.sin(c * math.pi * t + (0 if d == 0 else math.pi))
        e2 += (x - X - ud) ** 2
        de2 += (u(x) + u(X) * (1 + G * math.pi)) ** 2
    V0 = p.volume0.values
    l2 = wrms(V0, np.sqrt(e2), np.sqrt(de2))
    return {"u_L2_error": (l2[0] / G, l2[1] / G),
            "u_max_error": (np.sqrt(e2.max()) / G, np.sqrt(de2.max()) / G)}


def cooks_membrane(p, t, run):
    F, uy_ref, uy_ref_mid, r_fit = need(run.c, "F", "uy_ref", "uy_ref_mid", "r_fit")
    X, Y, y = p.X_x.values, p.X_y.values, p.y.values
    uy, duy = y - Y, u(y) + u(Y)

    def fitted(x0, y0):
        """u_y at (x0, y0) of the least-squares plane through the particles
        with X within r_fit, as the benchmark fits it; its bound is the sum
        of |d a / d u_y,i| times the rounding of u_y,i (a is linear in u_y)."""
        near = np.hypot(X - x0, Y - y0) <= r_fit
        phi = np.column_stack([np.ones(near.sum()), X[near] - x0, Y[near] - y0])
        if len(phi) < 3:
            return (math.nan, 0.0)
        A = phi.T @ phi
        if abs(np.linalg.det(A)) <= 1e-10 * (A[0, 0] * r_fit**2) ** 2:
            return (math.nan, 0.0)
        row = np.linalg.solve(A, np.eye(3)[0]) @ phi.T  # d a / d u_y
        return (float(row @ uy[near]), float(np.abs(row) @ duy[near]))

    corner, mid = fitted(48.0, 60.0), fitted(48.0, 52.0)
    # the nearest particle to the corner (by X; the first of a tie)
    k = int(np.argmin(np.hypot(X - 48.0, Y - 60.0)))
    return {"uy_corner": corner, "uy_mid": mid,
            "corner_ratio": (corner[0] / (F * uy_ref), corner[1] / abs(F * uy_ref)),
            "mid_ratio": (mid[0] / (F * uy_ref_mid), mid[1] / abs(F * uy_ref_mid)),
            "corner_nearest_ratio": (uy[k] / (F * uy_ref), duy[k] / abs(F * uy_ref))}


def water_column(p, t, run):
    a, g, rho = need(run.c, "a", "g", "rho")
    x, y, V = p.x.values, p.y.values, p.volume.values
    half, dhalf = 0.5 * np.sqrt(V), 0.25 * u(V) / np.sqrt(V)
    front = x + half
    k = int(np.argmax(front))
    wall = x < a / 10  # the benchmark's wall band
    top = y[wall] + half[wall]
    height = (top.max(), (u(y) + dhalf)[wall][np.argmax(top)]) if wall.any() else (0.0, 0.0)
    front = (front[k], u(x)[k] + dhalf[k])
    speed = np.hypot(p.v_x.values, p.v_y.values)
    out = {"x_front": front, "height": height,
           "Z": (front[0] / a, front[1] / a),
           "H": (height[0] / (2 * a), height[1] / (2 * a)),
           "max_speed": (speed.max(), (u(p.v_x.values) + u(p.v_y.values))[np.argmax(speed)])}
    if run.grid is not None:
        pm, dpm = pressure(p)
        cb, dcb, run.on_face = checkerboard(p, run.dim, run.grid, pm + rho * g * y,
                                            dpm + rho * g * u(y))
        head = rho * g * 2 * a
        out["checkerboard"] = (cb / head, dcb / head)
    return out


MEASURES = {"axial bar": axial_bar, "convecting bar": convecting_bar,
            "cantilever": cantilever, "spinning disk": spinning_disk,
            "self-weight column": self_weight_column, "thick cylinder": thick_cylinder,
            "manufactured solution": manufactured_solution, "cooks membrane": cooks_membrane,
            "water column": water_column}


def upward_crossings(t, v, dv):
    """Upward zero crossings by linear interpolation (beam_period.py), each
    with the bound of its move when the values move by at most dv."""
    out = []
    for i in range(len(t) - 1):
        if v[i] < 0 <= v[i + 1]:
            dt, du = t[i + 1] - t[i], v[i + 1] - v[i]
            tc = t[i] - v[i] * dt / du
            # d tc / d v_i = -dt v_{i+1}/du^2, d tc / d v_{i+1} = dt v_i/du^2
            out.append((tc, dt * (abs(v[i + 1]) * dv[i] + abs(v[i]) * dv[i + 1]) / du**2))
    return out


def period(crossings):
    if len(crossings) < 2:
        return None
    return ((crossings[-1][0] - crossings[0][0]) / (len(crossings) - 1),
            (crossings[-1][1] + crossings[0][1]) / (len(crossings) - 1))


class Run:
    pass


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("output_dir")
    ap.add_argument("--benchmark", help="benchmark name (default: from the parameters)")
    ap.add_argument("--prm", help="parameter file (default: OUTPUT_DIR/parameters.prm)")
    ap.add_argument("--all", action="store_true", help="print every row, not the first and last five")
    args = ap.parse_args()
    out = args.output_dir

    prm = args.prm or os.path.join(out, "parameters.prm")
    if not os.path.exists(prm):
        sys.exit(f"{prm} not found: give the run's parameter file with --prm")
    entries = read_prm(prm)
    run = Run()
    run.dim = int(entries.get("Dimension", "2"))
    run.c = constants(entries)
    run.grid = box_grid(entries, run.dim)
    run.on_face = 0
    name = args.benchmark or entries.get("Benchmark", "none")
    if name not in MEASURES:
        sys.exit(f"benchmark '{name}': none of {sorted(MEASURES)}")
    stats = pd.read_csv(os.path.join(out, "statistics.txt"), sep=r"\s+")

    files = sorted(glob.glob(os.path.join(out, "particles-*.csv")))
    rows = []  # (row, time, {column: (csv, bound)}, on_face)
    for f in files:
        k = int(re.search(r"particles-(\d+)\.csv$", f).group(1))
        if k >= len(stats):
            sys.exit(f"{f}: no statistics row {k} ({len(stats)} rows)")
        t = stats.time.iloc[k]
        run.on_face = 0
        rows.append((k, t, MEASURES[name](pd.read_csv(f), t, run), run.on_face))
    if not rows:
        print(f"{out}: no particle CSV files (Output/Write csv = false?)")
        sys.exit(2)

    columns = list(rows[0][2])
    missing = [c for c in columns if c not in stats.columns]
    if missing:
        sys.exit(f"statistics.txt has no column {missing}: not a '{name}' run?")
    if run.grid is None and name in ("self-weight column", "thick cylinder"):
        print("checkerboard: not recomputed (mesh-file grid: the CSV has no cell index)")

    print(f"{name}: {len(rows)} particle tables of {len(stats)} statistics rows in {out}")
    print(f"{'row':>5} {'time':>10} {'measure':>20} {'CSV':>14} {'statistics':>14} "
          f"{'|diff|':>9} {'allowed':>9}")
    worst_ratio, worst_rel, failed = 0.0, 0.0, []
    # relative differences are taken to the largest value of the column
    scales = {col: stats[col].iloc[[r[0] for r in rows]].abs().max() for col in columns}
    shown = set(range(len(rows))) if args.all else set(range(5)) | set(range(len(rows) - 5, len(rows)))
    for i, (k, t, measures, on_face) in enumerate(rows):
        for col in columns:
            v, bound = measures[col]
            s = stats[col].iloc[k]
            diff = abs(v - s)
            allowed = 2 * bound + 1e-9 * abs(s)
            bad = not diff <= allowed  # NaN disagrees
            if bad:
                failed.append(f"row {k} {col}: CSV {v:.10g} statistics {s:.12g}"
                              + (f" ({on_face} particles on a cell face)" if on_face else ""))
            worst_ratio = max(worst_ratio, diff / allowed if allowed > 0 else (0 if diff == 0 else math.inf))
            scale = scales[col]
            if scale > 0:
                worst_rel = max(worst_rel, diff / scale)
            if i in shown or bad:
                print(f"{k:5d} {t:10.5g} {col:>20} {v:14.8g} {s:14.8g} {diff:9.2e} {allowed:9.2e}"
                      + (" DISAGREE" if bad else ""))
        if i == 4 and len(rows) > 10 and not args.all:
            print(f"{'...':>5}")

    if name == "cantilever":
        # the period as beam_period.py takes it, from both series (every
        # statistics row must have its CSV for the two to be comparable)
        if len(rows) == len(stats):
            tt = stats.time.values
            vs = stats.tip_displacement_y.values
            vc = np.array([r[2]["tip_displacement_y"][0] for r in rows])
            bc = np.array([r[2]["tip_displacement_y"][1] for r in rows])
            dv = 2 * bc + 1e-9 * np.abs(vs)
            Ts, Tc = period(upward_crossings(tt, vs, dv)), period(upward_crossings(tt, vc, dv))
            if Ts is None or Tc is None:
                print("period: fewer than two upward zero crossings (run longer)")
            else:
                diff, allowed = abs(Ts[0] - Tc[0]), 2 * Ts[1] + 1e-9 * Ts[0]
                print(f"period: CSV {Tc[0]:.8g} s, statistics {Ts[0]:.8g} s, "
                      f"|diff| {diff:.2e}, allowed {allowed:.2e}")
                worst_ratio = max(worst_ratio, diff / allowed)
                if not diff <= allowed:
                    failed.append(f"period: CSV {Tc[0]} statistics {Ts[0]}")
        else:
            print("period: not compared (not every statistics row has its particle CSV)")

    on_face = max(r[3] for r in rows)
    if on_face:
        print(f"note: up to {on_face} particles within rounding of a cell face (checkerboard cell ambiguous)")
    print(f"largest difference relative to the column's largest value {worst_rel:.2e}; "
          f"largest |diff|/allowed {worst_ratio:.2e}")
    if failed:
        print("FAIL: the particle CSV and statistics.txt disagree:\n  " + "\n  ".join(failed))
        sys.exit(1)
    print(f"OK: {len(columns)} measures x {len(rows)} rows agree")


if __name__ == "__main__":
    main()
