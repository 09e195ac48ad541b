#!/usr/bin/env bash
# Sliding block (prm/sliding_block.prm, doc/benchmarks/sliding_block.md):
# an elastic block on a rigid plane inclined at theta = 30 degrees, Coulomb
# contact, for friction coefficients from 0 to 0.7 (tan theta = 0.577) on
# the grid of the parameter file (h = 0.05) and one twice as fine. Prints a
# table of the slide at t = 0.5 s against 1/2 g (sin theta - mu cos theta)
# t^2 and the error over the frictionless slide, and with FIGURE=1 writes
# doc/figures/sliding_block.png (slide against time for some mu). Then the
# plane drawn inclined (prm/sliding_block_rotated.prm) with its contact
# normal given and from its mass gradient, the rolling cylinder
# (prm/rolling_cylinder.prm; CYLINDER_MU overrides its mu values) with and
# without the gap check, and the block with the gap check (BLOCK_GAP_MU);
# FIGURE=1 also writes doc/figures/rolling_cylinder.png.
# Usage: scripts/sliding_block_study.sh [mu values...]   (MPM=..., RANKS=n)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# run MU GRID: run $work/case.prm and print its row of the table
run() {
  rm -rf "$work/out"
  local start=$(date +%s.%N)
  mpirun -np $ranks "$mpm" "$work/case.prm" > "$work/log"
  local wall=$(python3 -c "import time; print(f'{time.time() - $start:.1f}')")
  python3 - "$work/out/statistics.txt" "$1" "$2" "$wall" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1])]
head, last = rows[0], rows[-1]
v = dict(zip(head, last))
print(f"| {sys.argv[2]} | {sys.argv[3]} | {float(v['slide']):.4f} | "
      f"{float(v['slide_exact']):.4f} | {100 * float(v['slide_error']):+.2f}% | "
      f"{v['step']} | {sys.argv[4]} |")
PY
}
# write_case PRM MU REFINE GAP CONSTANT BODY0: prm/PRM.prm with friction
# MU, the grid and both bodies refined REFINE times (BODY0: body 0's
# refinement entry), Gap check = GAP, and one more CONSTANT
write_case() {
  cat > "$work/case.prm" <<PRM
include $root/prm/$1.prm
set Constants = theta=30, mu=$2, g=9.81, E=1e7, nu=0.3, rho=1000, $5
subsection Grid
  set Subdivisions = $((40 * $3)), $((15 * $3))
end
subsection Contact
  set Gap check = $4
end
subsection Output
  set Directory = $work/out
  set Interval = 0.025
  set Write vtu = false
end
subsection Bodies
  subsection Body 0
    $6
  end
  subsection Body 1
    set Subdivisions = $((40 * $3)), $((5 * $3))
  end
end
PRM
}
# block_case / cylinder_case MU REFINE GAP
block_case() {
  write_case sliding_block "$1" "$2" "$3" top=0.5 \
    "set Subdivisions = $((10 * $2)), $((5 * $2))"
}
cylinder_case() {
  write_case rolling_cylinder "$1" "$2" "$3" cylinder=1 \
    "set Refinements = $((2 + $2))"
}
echo "| mu | h | slide [m] | exact [m] | (slide - exact) / frictionless slide | steps | wall [s] |"
echo "|---|---|---|---|---|---|---|"
for mu in ${@:-0 0.1 0.2 0.3 0.4 0.5 0.55 0.6 0.7}; do
  for refine in 1 2; do
    h=$(python3 -c "print(0.05/$refine)")
    block_case "$mu" "$refine" false
    run "$mu" "$h"
    cp "$work/out/statistics.txt" "$work/stats_${mu}_${refine}.txt"
  done
done
# The plane drawn inclined across the cells, h = 0.05: with its Contact
# normal given, and with the normal from its mass gradient.
for mu in ${@:-0 0.3 0.5 0.7}; do
  for normal in given "mass gradient"; do
    cat > "$work/case.prm" <<PRM
include $root/prm/sliding_block_rotated.prm
set Constants = theta=30, beta=30, mu=$mu, g=9.81, E=1e7, nu=0.3, rho=1000, qx=0.373205080757, qy=1.2
subsection Output
  set Directory = $work/out
  set Write vtu = false
end
PRM
    [ "$normal" = given ] || printf 'subsection Bodies\n  subsection Body 1\n    set Contact normal =\n  end\nend\n' >> "$work/case.prm"
    run "$mu" "0.05, inclined plane, normal $normal"
  done
done
# The solid cylinder (prm/rolling_cylinder.prm): it slides below
# mu = tan(theta)/3 = 0.192 and rolls above; with the gap check of the
# parameter file and without it.
for gap in true false; do
  for mu in ${CYLINDER_MU:-0 0.1 0.3 0.5}; do
    for refine in 1 2; do
      h=$(python3 -c "print(0.05/$refine)")
      cylinder_case "$mu" "$refine" "$gap"
      run "$mu" "$h, cylinder, gap check $gap"
      cp "$work/out/statistics.txt" "$work/cylinder_${gap}_${mu}_${refine}.txt"
    done
  done
done
# The block with the gap check, which the cylinder needs: far from
# sticking it changes nothing, near it the block creeps more.
for mu in ${BLOCK_GAP_MU:-0.3 0.5}; do
  for refine in 1 2; do
    h=$(python3 -c "print(0.05/$refine)")
    block_case "$mu" "$refine" true
    run "$mu" "$h, gap check"
  done
done
if [ "${FIGURE:-0}" = 1 ]; then
  /usr/bin/python3 "$root/scripts/plot_sliding_block.py" "$work" \
    "$root/doc/figures/sliding_block.png"
  /usr/bin/python3 "$root/scripts/plot_rolling_cylinder.py" "$work" \
    "$root/doc/figures/rolling_cylinder.png"
fi
