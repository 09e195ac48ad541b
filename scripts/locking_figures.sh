#!/usr/bin/env bash
# Regenerate the results and figures of the locking remedies on the
# benchmarks (doc/benchmarks/): the cantilever, the self-weight column, the thick
# cylinder and the convecting bar studies into results/, their figures into doc/figures/.
# About 15 minutes on the 2-core development machine.
# Usage: scripts/locking_figures.sh
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$root/results" "$root/doc/figures"
"$root/scripts/cantilever_study.sh" "$root/results/cantilever"
/usr/bin/python3 "$root/scripts/plot_cantilever.py" "$root/results/cantilever" \
  "$root/doc/figures/cantilever_period.png"
"$root/scripts/column_study.sh" "$root/results/column"
/usr/bin/python3 "$root/scripts/plot_column.py" "$root/results/column" \
  "$root/doc/figures/self_weight_column.png"
"$root/scripts/thick_cylinder_study.sh" "$root/results/thick-cylinder"
/usr/bin/python3 "$root/scripts/plot_thick_cylinder.py" "$root/results/thick-cylinder" \
  "$root/doc/figures/thick_cylinder.png"
"$root/scripts/run_convecting_bar.sh" "$root/results/convecting-bar"
cp "$root/results/convecting-bar/convecting_bar.png" "$root/doc/figures/convecting_bar.png"
