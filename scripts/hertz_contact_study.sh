#!/usr/bin/env bash
# Hertzian contact (prm/hertz_contact.prm, doc/benchmarks/hertz_contact.md):
# an elastic cylinder, R = 0.5 m, resting by its weight on a rigid plane,
# on grids refined LEVELS times (k = 1 2 4 8: h = 0.05 / k, Hertz's
# half-width a = 0.1 m = 2k cells; the cylinder's ball mesh refined with
# the grid) and with PPDS particles per direction of its cells (4 and 2).
# Prints a table of the load, half-width and peak pressure at t = 0.25 s
# against Hertz's, and writes each run's contact forces to RESULTS
# (default results/hertz_contact); with FIGURE=1 also
# doc/figures/hertz_contact.png (scripts/plot_hertz_contact.py).
# Usage: scripts/hertz_contact_study.sh [RESULTS]
#        (MPM=..., RANKS=n, LEVELS="1 2 4 8", PPDS="4 2", FIGURE=1)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
results=${1:-$root/results/hertz_contact}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$results"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| h | a / h | particles per direction | load / weight | a | a Hertz | error | p0 | p0 Hertz | error | steps | wall [s] |"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
for ppd in ${PPDS:-4 2}; do
  for k in ${LEVELS:-1 2 4 8}; do
    refinements=$((2 + $(python3 -c "import math; print(round(math.log2($k)))")))
    name="k${k}_ppd${ppd}"
    cat > "$work/case.prm" <<PRM
include $root/prm/hertz_contact.prm
subsection Grid
  set Subdivisions = $((24 * k)), $((22 * k))
end
subsection Output
  set Directory = $work/out
  set Interval = 0.25
end
subsection Bodies
  subsection Body 0
    set Refinements = $refinements
    set Particles per direction = $ppd
  end
  subsection Body 1
    set Subdivisions = $((24 * k)), $k
  end
end
PRM
    rm -rf "$work/out"
    start=$(date +%s.%N)
    mpirun -np "$ranks" "$mpm" "$work/case.prm" > "$work/log"
    wall=$(python3 -c "import time; print(f'{time.time() - $start:.0f}')")
    last=$(ls "$work"/out/contact-*.csv | tail -1)
    cp "$last" "$results/$name.csv"
    cp "$work/out/statistics.txt" "$results/$name.statistics.txt"
    python3 - "$work/out/statistics.txt" "$k" "$ppd" "$wall" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1])]
v = dict(zip(rows[0], rows[-1]))
k, ppd, wall = int(sys.argv[2]), sys.argv[3], sys.argv[4]
# the weight: G times the cylinder's mass, the particles' less the plane's
# (rho times its 1.2 m x 0.05 m)
weight = 220 * (float(v['mass']) - 1000 * 1.2 * 0.05)
f = lambda c: float(v[c])
print(f"| {0.05 / k:g} | {2 * k} | {ppd} | {f('contact_load') / weight:.4f} | "
      f"{f('half_width'):.4f} | {f('half_width_exact'):.4f} | "
      f"{100 * f('half_width_error'):+.1f}% | {f('peak_pressure'):.4g} | "
      f"{f('peak_pressure_exact'):.4g} | {100 * f('peak_pressure_error'):+.1f}% | "
      f"{v['step']} | {wall} |")
PY
  done
done
if [ "${FIGURE:-0}" = 1 ]; then
  /usr/bin/python3 "$root/scripts/plot_hertz_contact.py" "$results" \
    "$root/doc/figures/hertz_contact.png"
fi
