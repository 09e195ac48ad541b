#!/usr/bin/python3
"""Water column collapse (doc/benchmarks/water_column.md): compare runs of
prm/water_column.prm with Martin & Moyce (1952).

For each run folder (its statistics.txt, columns of Benchmark = water
column) this prints one table row: the RMS difference of the surge front
Z = x/a over the 15 experimental T = t sqrt(2g/a) points and of the
height H = h/(2a) over the 17 tau = t sqrt(g/a) points, the simulated
curves interpolated linearly at the data times (no time shift); the same
with the time shift dT of the simulated front that minimises its RMS
(information only: the experimental origin of time is uncertain); the
pressure checkerboard (mean over the outputs with T <= 3.4, and at the
output nearest T = 2); the T the run reached (a run that stopped early
has no RMS: nan); the largest particle speed up to T = 3.4 and over
the whole run, c over the first, and the mass removed (particles that
left the grid) in per cent of the total.
With --check-csv the front and height are recomputed from the particle
CSV files (x + sqrt(V)/2) and the largest difference to statistics.txt is
printed.

With --modes it prints instead, from the particle CSV files, the
checkerboard recomputed (RMS jump of the cells' p + rho g y between face
neighbours) and its checkerboard-mode part (RMS over 2x2 blocks of
(p00 - p10 - p01 + p11)/4, zero for any bilinear field), both in units of
rho g 2a, as means over T <= 3.4 and at T = 2.

With --front it prints instead where the front's error comes from: the
mean of Z - data over the four early points (T <= 1.43, the collapse of
the deep column) and over the eight late ones (T >= 2.2, the thin
spreading layer), the front speed dZ/dT fitted over the late points
(data: 1.38), and, from the particle files, the RMS of fronts tracked by
depth instead of by the foremost particle: the furthest x where the
layer is at least a/40, a/20, a/10 or a/5 deep (the particles' area in
columns a/20 wide), each with its best time shift.

With --height-to TAU it prints instead the RMS of H over the height
points with tau <= TAU only (for runs that end early, e.g. the fine
grids to tau = 2.5) and the differences at tau = 1.28, 1.84 and 2.45.

Usage: water_column_rms.py [--check-csv] [--c SOUND_SPEED] RUN_DIR...
       water_column_rms.py --front RUN_DIR...
       water_column_rms.py --modes RUN_DIR...
       water_column_rms.py --height-to TAU RUN_DIR..."""
import glob
import sys

import numpy as np
import pandas as pd

from recompute_measures import Run, box_grid, cell_averages, read_prm, water_column

A = 0.05715
RHO, G = 1000.0, 9.81
# Martin & Moyce 1952 (a = 2.25 in = 0.05715 m, height 2a): surge front
# Z = x/a at T = t sqrt(2g/a), column height H = h/(2a) at tau = t sqrt(g/a)
T_DATA = np.array([0.41, 0.84, 1.19, 1.43, 1.63, 1.83, 1.98, 2.20, 2.32,
                   2.51, 2.65, 2.83, 2.98, 3.11, 3.33])
Z_DATA = np.array([1.11, 1.22, 1.44, 1.67, 1.89, 2.11, 2.33, 2.56, 2.78,
                   3.00, 3.22, 3.44, 3.67, 3.89, 4.11])
TAU_DATA = np.array([0.56, 0.77, 0.93, 1.08, 1.28, 1.46, 1.66, 1.84, 2.00,
                     2.21, 2.45, 2.70, 3.06, 3.44, 4.20, 5.25, 7.40])
H_DATA = np.array([0.94, 0.89, 0.83, 0.78, 0.72, 0.67, 0.61, 0.56, 0.50,
                   0.44, 0.39, 0.33, 0.28, 0.22, 0.17, 0.11, 0.06])
T_SNAPSHOT = 2.0


def statistics(run):
    return pd.read_csv(f"{run}/statistics.txt", sep=r"\s+")


def rms_front(s, shift=0.0):
    if s["T"].iloc[-1] < T_DATA[-1] + shift:
        return np.nan
    Z = np.interp(T_DATA + shift, s["T"], s["Z"])
    return np.sqrt(np.mean((Z - Z_DATA) ** 2))


def rms_height(s):
    if s["tau"].iloc[-1] < TAU_DATA[-1]:
        return np.nan
    return rms_height_to(s, TAU_DATA[-1])[0]


def rms_height_to(s, tau_max):
    """RMS of H over the data points with tau <= tau_max, and the
    differences at every such point."""
    m = TAU_DATA <= tau_max + 1e-12
    d = np.interp(TAU_DATA[m], s["tau"], s["H"]) - H_DATA[m]
    return np.sqrt(np.mean(d ** 2)), dict(zip(TAU_DATA[m], d))


def best_shift(s):
    """The shift dT (simulated T = experimental T + dT) in [-1, 1] that
    minimises the front RMS, on a grid of 0.005."""
    shifts = np.arange(-1.0, 1.0 + 1e-9, 0.005)
    r = np.array([rms_front(s, d) for d in shifts])
    if np.all(np.isnan(r)):
        return np.nan, np.nan
    i = np.nanargmin(r)
    return shifts[i], r[i]


def check_csv(run, s):
    """The largest difference of front and height recomputed from the
    particle CSV files (recompute_measures.water_column) to statistics.txt."""
    case = Run()
    case.c, case.dim, case.grid = {"a": A, "g": G, "rho": RHO}, 2, None
    worst = 0.0
    for k, f in enumerate(sorted(glob.glob(f"{run}/particles-*.csv"))):
        m = water_column(pd.read_csv(f), s.time[k], case)
        worst = max(worst, abs(m["x_front"][0] - s.x_front[k]),
                    abs(m["height"][0] - s.height[k]))
    return worst


def cell_pressure(run, f):
    """The cells' volume-averaged p + rho g y of one particle table, on the
    run's box grid, as an (ny, nx) array (nan: no particle)."""
    d = pd.read_csv(f)
    p = -(d.stress_xx + d.stress_yy + d.stress_zz).values / 3 + RHO * G * d.y.values
    grid = box_grid(read_prm(f"{run}/parameters.prm"), 2)
    return cell_averages(d, 2, grid, p, 0 * p)[0].T


def checkerboard_measures(P):
    """(jump, mode) in units of rho g 2a. jump: the RMS of the pressure jump
    between face-neighbouring filled cells (the statistics' checkerboard,
    recomputed); mode: the RMS over the 2x2 blocks of filled cells of the
    checkerboard component (p00 - p10 - p01 + p11)/4, which is zero for
    any bilinear field, so smooth pressure variation does not count."""
    jumps = np.concatenate([(P[:, 1:] - P[:, :-1]).ravel(), (P[1:, :] - P[:-1, :]).ravel()])
    jumps = jumps[np.isfinite(jumps)]
    mode = (P[:-1, :-1] - P[1:, :-1] - P[:-1, 1:] + P[1:, 1:]) / 4
    mode = mode[np.isfinite(mode)]
    scale = RHO * G * 2 * A
    return np.sqrt(np.mean(jumps**2)) / scale, np.sqrt(np.mean(mode**2)) / scale


def checkerboard_modes(run, s):
    """The mean of both measures over the particle tables with T <= 3.4,
    and both at the table nearest T = 2."""
    files = sorted(glob.glob(f"{run}/particles-*.csv"))
    rows = [(s["T"][k],) + checkerboard_measures(cell_pressure(run, f))
            for k, f in enumerate(files) if s["T"][k] <= 3.4]
    r = np.array(rows)
    k = int(np.argmin(np.abs(r[:, 0] - T_SNAPSHOT)))
    return r[:, 1].mean(), r[:, 2].mean(), r[k, 1], r[k, 2]


EARLY, LATE = T_DATA <= 1.43 + 1e-12, T_DATA >= 2.2 - 1e-12
DEPTHS, COLUMN = (A / 40, A / 20, A / 10, A / 5), A / 20


def front_speed(T, Z):
    """dZ/dT, least squares over the late data times."""
    return np.polyfit(T[LATE], Z[LATE], 1)[0]


def depth_fronts(f):
    """For each depth of DEPTHS, the furthest x where the layer is at least
    that deep: the particles' area summed in columns COLUMN wide from the
    wall, its depth (area over width) interpolated linearly between
    column centres."""
    d = pd.read_csv(f)
    n = int(np.ceil(d.x.max() / COLUMN)) + 1
    depth = np.bincount((d.x.values / COLUMN).astype(int),
                        weights=d.volume.values, minlength=n) / COLUMN
    centre = (np.arange(len(depth)) + 0.5) * COLUMN
    fronts = []
    for h in DEPTHS:
        i = np.nonzero(depth >= h)[0][-1]
        if i + 1 == len(depth):
            fronts.append(centre[i])
        else:  # where the depth falls below h between centres i and i + 1
            fronts.append(centre[i] + COLUMN * (depth[i] - h) / (depth[i] - depth[i + 1]))
    return fronts


def front_sources(run, s):
    """The early and late mean errors and the late speed of the tracked
    front; then, for each depth of DEPTHS, the RMS, best shift and RMS at
    that shift of the front tracked by depth (nan where the run has no
    particle files)."""
    Z = np.interp(T_DATA, s["T"], s["Z"])
    row = [np.mean(Z[EARLY] - Z_DATA[EARLY]), np.mean(Z[LATE] - Z_DATA[LATE]),
           front_speed(T_DATA, Z)]
    files = sorted(glob.glob(f"{run}/particles-*.csv"))
    if not files:
        return row + [np.nan] * 3 * len(DEPTHS)
    t = s["T"].values[:len(files)]
    keep = t <= T_DATA[-1] + 1.1
    fronts = np.array([depth_fronts(f) for f, k in zip(files, keep) if k]) / A
    for j in range(len(DEPTHS)):
        tracked = pd.DataFrame({"T": t[keep], "Z": fronts[:, j]})
        row += [rms_front(tracked), *best_shift(tracked)]
    return row


def main(argv):
    if "--front" in argv:
        print(f"| run | Z - data, T <= 1.43 | Z - data, T >= 2.2 | dZ/dT, T >= 2.2 "
              f"(data {front_speed(T_DATA, Z_DATA):.2f}) | "
              + " | ".join(f"depth a/{A / h:.0f}: RMS Z (best dT: RMS)" for h in DEPTHS)
              + " |")
        print("|---" * (4 + len(DEPTHS)) + "|")
        for run in [a for a in argv if a != "--front"]:
            r = front_sources(run, statistics(run))
            depth = [f"{r[k]:.3f} ({r[k + 1]:+.3f}: {r[k + 2]:.3f})"
                     for k in range(3, len(r), 3)]
            print(f"| {run.rstrip('/').split('/')[-1]} | {r[0]:+.3f} | {r[1]:+.3f} "
                  f"| {r[2]:.2f} | " + " | ".join(depth) + " |")
        return
    if "--height-to" in argv:
        i = argv.index("--height-to")
        tau_max = float(argv[i + 1])
        del argv[i:i + 2]
        print(f"| run | RMS H, tau <= {tau_max} | H - data at tau = 1.28 / 1.84 / 2.45 |")
        print("|---|---|---|")
        for run in argv:
            r, d = rms_height_to(statistics(run), tau_max)
            at = " / ".join(f"{d[t]:+.3f}" if t in d else "-"
                            for t in (1.28, 1.84, 2.45))
            print(f"| {run.rstrip('/').split('/')[-1]} | {r:.3f} | {at} |")
        return
    if "--modes" in argv:
        # the checkerboard recomputed from the particle tables, and its
        # component orthogonal to bilinear fields
        print("| run | jump, mean T<=3.4 | mode, mean T<=3.4 | jump at T=2 | mode at T=2 |")
        print("|---|---|---|---|---|")
        for run in [a for a in argv if a != "--modes"]:
            r = checkerboard_modes(run, statistics(run))
            print(f"| {run.rstrip('/').split('/')[-1]} | " + " | ".join(f"{v:.4f}" for v in r) + " |")
        return
    check = "--check-csv" in argv
    argv = [a for a in argv if a != "--check-csv"]
    c = None
    if "--c" in argv:
        i = argv.index("--c")
        c = float(argv[i + 1])
        del argv[i:i + 2]
    print("| run | end T | RMS Z (15 pts) | RMS H (17 pts) | best dT | RMS Z at best dT "
          "| checkerboard, mean T<=3.4 | checkerboard at T=2 | max speed T<=3.4 [m/s]"
          + " | max speed, whole run | removed mass [%]"
          + (" | c / max speed (T<=3.4)" if c else "")
          + (" | CSV check [m]" if check else "") + " |")
    print("|---" * (11 + bool(c) + check) + "|")
    for run in argv:
        s = statistics(run)
        shift, r_shift = best_shift(s)
        collapse = s[s["T"] <= 3.4]
        k = (s["T"] - T_SNAPSHOT).abs().idxmin()
        row = [run.rstrip("/").split("/")[-1], f"{s['T'].iloc[-1]:.2f}",
               f"{rms_front(s):.3f}", f"{rms_height(s):.3f}",
               f"{shift:+.3f}", f"{r_shift:.3f}",
               f"{collapse.checkerboard.mean():.4f}",
               f"{s.checkerboard[k]:.4f} (T={s['T'][k]:.2f})",
               f"{collapse.max_speed.max():.3f}",
               f"{s.max_speed.max():.3f}",
               f"{100 * s.removed_mass.iloc[-1] / s.mass[0]:.3f}"]
        if c:
            row.append(f"{c / collapse.max_speed.max():.1f}")
        if check:
            row.append(f"{check_csv(run, s):.1e}")
        print("| " + " | ".join(row) + " |")


if __name__ == "__main__":
    main(sys.argv[1:])
