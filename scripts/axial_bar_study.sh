#!/usr/bin/env bash
# Axial vibration of a fixed-free bar (doc/benchmarks/axial_bar.md,
# prm/axial_bar.prm; exact standing wave v = v0 cos(omega t) sin(beta x),
# beta = pi/(2L)): standard MPM, uGIMP and CPDI on 16 and 32 cells
# (2 particles per cell, dt = 0.2 h/c), 10 s (one period 4L/c of the
# first mode), output every 0.05 s with particle CSV files. Writes
# OUT/table.txt (the centre-of-mass velocity error and the RMS velocity
# error, largest over the run and at the end, divided by v0) and the
# figure (scripts/plot_axial_bar.py). About 5 s.
# Usage: scripts/axial_bar_study.sh [OUT] [PNG]
#   defaults results/axial-bar and doc/figures/axial_bar.png
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-$root/results/axial-bar}")
png=$(realpath -m "${2:-$root/doc/figures/axial_bar.png}")
mpm=${MPM:-$root/build/mpm}
mkdir -p "$out"
for cells in 16 32; do
  for family in standard uGIMP CPDI; do
    dir="$out/${family}_n${cells}"
    rm -rf "$dir"; mkdir -p "$dir"
    # grid 18/16 of the bar long, h = L/cells; dt = 0.2 h/c, c = 10 m/s
    cat > "$dir/case.prm" <<PRM
include $root/prm/axial_bar.prm
subsection Grid
  set Subdivisions = $(( cells * 18 / 16 ))
end
subsection Time stepping
  set Time step = $(awk -v n=$cells 'BEGIN{printf "%.17g", 0.2 * 25 / n / 10}')
end
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Output
  set Directory = $dir
  set Interval = 0.05
  set Write vtu = false
  set Write csv = true
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $cells
  end
end
PRM
    "$mpm" "$dir/case.prm" > "$dir/log.txt" 2>&1 ||
      { echo "$family n=$cells failed: $(grep -m1 'mpm:' "$dir/log.txt")" >&2; exit 1; }
  done
done
/usr/bin/python3 "$root/scripts/plot_axial_bar.py" "$out" "$png"
