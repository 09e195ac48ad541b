#!/usr/bin/python3
"""Spinning disk, the seed's pictures: particles coloured by sigma_rr/sigma0
(top row) and sigma_rt/sigma0 (bottom row) at the last output, one column
per variant, each row on one colour scale.

Usage: plot_spinning_disk_variants.py STUDY_DIR PNG VARIANT... [--target]
                                      [--table] [--title TEXT]
STUDY_DIR is a directory written by scripts/spinning_disk_study.sh: one
folder per variant and errors.csv. The RMS errors in the titles are the
code's (errors.csv, from statistics.txt); without errors.csv they are
computed here from the particles. --target adds a last column with the
exact field at the particles of the first variant; --table prints the
errors of every variant as a table."""
import argparse
import glob
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import pandas as pd

parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
parser.add_argument("study")
parser.add_argument("png")
parser.add_argument("variants", nargs="+")
parser.add_argument("--target", action="store_true",
                    help="add a column with the exact field")
parser.add_argument("--table", action="store_true",
                    help="print the errors of every variant as a table")
parser.add_argument("--title", default=None, help="title over the picture")
args = parser.parse_args()

rho, omega, nu, a = 1000.0, 1.0, 0.3, 1.0
sigma0 = rho * omega**2 * (3 + nu) * a**2 / 8


def label(variant):
    """Readable name of a variant such as CPDI+filter+force+APIC."""
    parts = variant.split("+")
    name = "standard MPM" if parts[0] == "standard" else parts[0]
    if "enriched" in parts:
        name += " + filter (enriched)"
    elif "filter" in parts:
        name += " + filter"
    if "force" in parts:
        name += ",\nforce only"
    if "APIC" in parts:
        name += " + APIC"
    return name


def polar(d):
    """sigma_rr, sigma_rt and the exact sigma_rr at the particles of d."""
    r = np.hypot(d.x, d.y)
    c, s = d.x / np.maximum(r, 1e-300), d.y / np.maximum(r, 1e-300)
    srr = c * c * d.stress_xx + s * s * d.stress_yy + 2 * c * s * d.stress_xy
    srt = (d.stress_yy - d.stress_xx) * c * s + (c * c - s * s) * d.stress_xy
    exact = rho * omega**2 / 8 * (3 + nu) * (a**2 - r**2)
    return srr, srt, exact


table = None
if os.path.exists(f"{args.study}/errors.csv"):
    table = pd.read_csv(f"{args.study}/errors.csv").set_index("variant")

columns = list(args.variants) + (["target"] if args.target else [])
n = len(columns)
fig, axes = plt.subplots(2, n, figsize=(1.95 * n + 0.8, 5.2),
                         constrained_layout=True, squeeze=False)
rows = [("sigma_rr", r"$\sigma_{rr}/\sigma_0$", (0, 1)),
        ("sigma_rt", r"$\sigma_{r\theta}/\sigma_0$", (-0.2, 0.2))]
scatters, first, errors = [], None, {}
for col, v in enumerate(columns):
    for row in range(2):
        ax = axes[row, col]
        ax.set_aspect("equal")
        ax.set_xlim(-1.1, 1.1)
        ax.set_ylim(-1.1, 1.1)
        ax.set_xticks([])
        ax.set_yticks([])
    if v == "target":
        if first is None:
            axes[0, col].set_title("target\n(no particles)", fontsize=9)
            continue
        d = first
        _, _, exact = polar(d)
        values = [exact / sigma0, np.zeros(len(d))]
        titles = ["target (exact)\n" + r"$\sigma_{rr}$", r"$\sigma_{r\theta} = 0$"]
    else:
        files = sorted(glob.glob(f"{args.study}/{v}/output/particles-*.csv"))
        failed = table is not None and v in table.index and table.t[v] == "failed"
        if failed or not files:
            axes[0, col].set_title(f"{label(v)}\n(failed)", fontsize=9)
            errors[v] = (np.nan, np.nan)
            continue
        d = pd.read_csv(files[-1])
        if first is None:
            first = d
        srr, srt, exact = polar(d)
        if table is not None and v in table.index:
            err_rr = float(table.sigma_rr_rms_error[v])
            err_rt = float(table.sigma_rt_rms[v])
        else:
            err_rr = np.sqrt(np.average(((srr - exact) / sigma0)**2, weights=d.mass))
            err_rt = np.sqrt(np.average((srt / sigma0)**2, weights=d.mass))
        errors[v] = (err_rr, err_rt)
        values = [srr / sigma0, srt / sigma0]
        titles = [f"{label(v)}\n" + r"RMS error $\sigma_{rr}$: " + f"{err_rr:.3g}",
                  r"RMS $\sigma_{r\theta}$: " + f"{err_rt:.3g}"]
    for row, (name, cbar_label, lim) in enumerate(rows):
        ax = axes[row, col]
        sc = ax.scatter(d.x, d.y, c=values[row], s=1, cmap="jet",
                        vmin=lim[0], vmax=lim[1], linewidths=0)
        scatters.append((sc, ax, np.sqrt(d.volume.mean())))
        ax.set_title(titles[row], fontsize=9)
for row, (name, cbar_label, lim) in enumerate(rows):
    sm = plt.cm.ScalarMappable(cmap="jet", norm=plt.Normalize(*lim))
    fig.colorbar(sm, ax=axes[row, :], shrink=0.85, fraction=0.025,
                 pad=0.01, aspect=15, label=cbar_label)
if args.title:
    fig.suptitle(args.title, fontsize=10)
# markers as large as a particle's domain, so the disk looks filled
fig.canvas.draw()
for sc, ax, spacing in scatters:
    points_per_unit = ax.get_window_extent().width / fig.dpi * 72 / 2.2
    sc.set_sizes([(1.3 * spacing * points_per_unit)**2])
fig.savefig(args.png, dpi=110)

if args.table:
    head = f"{'variant':<42} {'sigma_rr RMS error':>18} {'sigma_rt RMS':>12}"
    extra = table is not None
    if extra:
        head += f" {'v_r RMS':>9} {'dL_z/L_z':>9} {'dE/E':>9} {'wall s':>6}"
    print(head)
    for v in args.variants:
        err_rr, err_rt = errors[v]
        if np.isnan(err_rr):
            print(f"{label(v).replace(chr(10), ' '):<42} {'failed':>18}")
            continue
        line = f"{label(v).replace(chr(10), ' '):<42} {err_rr:>18.4g} {err_rt:>12.4g}"
        if extra and v in table.index:
            t = table.loc[v]
            line += f" {t.v_r_rms:>9.3g} {t.angular_momentum_change:>9.2g}" \
                    f" {t.energy_change:>9.2g} {int(t.wall_s):>6}"
        print(line)
    print("(over sigma0 = rho omega^2 (3 + nu) a^2 / 8 = "
          f"{sigma0:.1f} Pa, mass-weighted, at the end time)")
print(f"wrote {args.png}")
