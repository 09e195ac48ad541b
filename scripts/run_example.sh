#!/usr/bin/env bash
# One command from a fresh Debian 12 machine: install, build, and run the
# default example (the spinning disk, 2D, about half a minute), then plot it.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh" mpm
mkdir -p "$root/results"
cd "$root/results"
"$root/build/mpm" "$root/prm/spinning_disk.prm"
/usr/bin/python3 "$root/scripts/plot_spinning_disk.py" output-spinning-disk spinning_disk.png
echo
echo "Results:  $root/results/output-spinning-disk/ (open particles.pvd in ParaView;"
echo "          statistics.txt has energies, momenta and the sigma_rr / sigma_rt errors)"
echo "Picture:  $root/results/spinning_disk.png"
