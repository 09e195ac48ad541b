#!/usr/bin/python3
"""Water column collapse (BENCHMARKS.md section 6): compare runs of
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

Usage: water_column_rms.py [--check-csv] [--c SOUND_SPEED] RUN_DIR... """
import glob
import sys

import numpy as np
import pandas as pd

A = 0.05715
# Martin & Moyce 1952, BENCHMARKS.md section 6
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
    H = np.interp(TAU_DATA, s["tau"], s["H"])
    return np.sqrt(np.mean((H - H_DATA) ** 2))


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
    worst = 0.0
    for k, f in enumerate(sorted(glob.glob(f"{run}/particles-*.csv"))):
        d = pd.read_csv(f)
        half = 0.5 * np.sqrt(d.volume)
        front = (d.x + half).max()
        wall = d.x < A / 10
        height = (d.y[wall] + half[wall]).max() if wall.any() else 0.0
        worst = max(worst, abs(front - s.x_front[k]), abs(height - s.height[k]))
    return worst


def main(argv):
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
