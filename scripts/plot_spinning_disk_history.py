#!/usr/bin/env python3
"""Error history of the spinning-disk runs of scripts/spinning_disk_sweep.sh.

Usage: plot_spinning_disk_history.py OUT PNG

Reads OUT/w<omega>_nu<nu>_n<cells>/<variant>/output/statistics.txt and
draws the RMS
errors of sigma_rr and sigma_rt (over sigma0) against the number of turns,
one line per run, with the 0.5% and 1% marks.
"""
import math
import pathlib
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def read(path):
    lines = path.read_text().split("\n")
    header = lines[0].split()
    rows = [list(map(float, l.split())) for l in lines[1:] if l.strip()]
    return {name: [r[i] for r in rows] for i, name in enumerate(header)}


def main():
    out, png = pathlib.Path(sys.argv[1]), sys.argv[2]
    runs = sorted(out.glob("w*_nu*_n*/*/output/statistics.txt"))
    if not runs:
        sys.exit(f"{out}: no runs (w*_nu*_n*/*/output/statistics.txt)")
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2), sharex=True)
    for path in runs:
        name = path.parent.parent.parent.name
        w, nu, n = re.match(r"w(.+)_nu(.+)_n(.+)", name).groups()
        period = 2 * math.pi / float(w)
        s = read(path)
        turns = [t / period for t in s["time"]]
        label = f"omega {w}, nu {nu}, h {2.5 / float(n):.3g}"
        for ax, column in zip(axes, ["sigma_rr_rms_error", "sigma_rt_rms"]):
            ax.semilogy(turns[1:], [max(v, 1e-7) for v in s[column][1:]],
                        lw=0.9, label=label)
    for ax, title in zip(axes, [r"RMS $(\sigma_{rr}-\sigma_{rr}^{exact})/\sigma_0$",
                                r"RMS $\sigma_{r\theta}/\sigma_0$"]):
        ax.axhline(0.005, color="k", ls="--", lw=0.7)
        ax.axhline(0.01, color="k", ls=":", lw=0.7)
        ax.set_xlabel("turns")
        ax.set_title(title)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"wrote {png}")


if __name__ == "__main__":
    main()
