#!/usr/bin/env bash
# Throughput (doc/performance.md): particle-updates per second of the time
# loop (particles x steps / wall seconds of the loop) and peak memory per
# particle, on 1 and 2 ranks, as printed by mpm itself, for the unit square
# block of prm/throughput_2d.prm (2x2 particles per cell, 100 steps, no
# output).
# Usage: scripts/throughput.sh [cells] [variant] [ranks]
#   cells:   cells inside the block per direction (256 or 512)
#   variant: standard (default), filter (assumed-stress filter, mass
#            metric), theta-bar, uGIMP, cpGIMP, CPDI, CPDI2; corner: the
#            block in one corner of a grid [-0.25, 2.25]^2 without load
#            balancing (p4est's equal cell counts give most particles to
#            one rank); corner-balanced: the same balanced at set-up and
#            every 50 steps; unbalanced: standard without the set-up
#            balance; wide: standard in a grid of four times the area,
#            [-1, 2]^2, around the same block; neo-Hookean, von-Mises:
#            standard with those materials. All but corner and
#            unbalanced are balanced at set-up (Load balancing/Balance at
#            set-up, on by default).
#   ranks:   the rank counts to run, e.g. "1" or "1 2" (default)
# DIM=3: the same in 3D (prm/throughput_3d.prm; cells default 32, i.e.
# 262 144 particles as the 2D default).
# Run it on an otherwise idle machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm} # MPM=...: another build, for A/B runs
dim=${DIM:-2}
[ "$dim" = 2 ] || [ "$dim" = 3 ] || { echo "DIM must be 2 or 3" >&2; exit 1; }
default_cells=256
[ "$dim" = 3 ] && default_cells=32
cells=${1:-$default_cells}
variant=${2:-standard}
ranks=${3:-1 2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
"$root/scripts/throughput_case.sh" "$dim" "$cells" "$variant" > "$work/case.prm"
cd "$work"
for np in $ranks; do
  mpirun -np $np "$mpm" case.prm > log.$np
  echo "$variant, ranks $np, ${cells}^$dim block: $(sed -n 's/^  particles: //p' log.$np) particles"
  grep -E "time loop:|memory:|load balancing:" log.$np
done
rm -rf "$work"
