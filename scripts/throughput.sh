#!/usr/bin/env bash
# BENCHMARKS.md section 10: particle-updates per second of the time loop and
# peak memory per particle, on 1 and 2 ranks, as printed by mpm itself.
# Usage: scripts/throughput.sh [cells] [variant] [ranks]
#   cells:   cells inside the block per direction (256 or 512)
#   variant: standard (default), filter (assumed-stress filter, mass
#            metric), theta-bar, uGIMP, cpGIMP, CPDI, CPDI2; corner: the
#            block in one corner of a grid [-0.25, 2.25]^2 without load
#            balancing (p4est's equal cell counts give most particles to
#            one rank); corner-balanced: the same balanced at set-up and
#            every 50 steps; unbalanced: standard without the set-up
#            balance. All but corner and unbalanced are balanced at set-up
#            (Load balancing/Balance at set-up, on by default).
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
family=standard remedy="" upper=1.25 grid=$((cells * 3 / 2)) interval=0
at_setup=true
case "$variant" in
  standard) ;;
  unbalanced) at_setup=false ;;
  corner) upper=2.25 grid=$((cells * 5 / 2)) at_setup=false ;;
  corner-balanced) upper=2.25 grid=$((cells * 5 / 2)) interval=50 ;;
  filter) remedy="set Stress filter = assumed stress" ;;
  theta-bar) remedy="set Volumetric smoothing = cell" ;;
  uGIMP|cpGIMP|CPDI|CPDI2) family=$variant ;;
  *) echo "unknown variant '$variant'" >&2; exit 1 ;;
esac
work=$(mktemp -d)
corner=$upper
[ "$dim" = 3 ] && corner="$upper, $upper"
cat > "$work/case.prm" <<PRM
include $root/prm/throughput_${dim}d.prm
subsection Grid
  set Upper corner = $upper, $corner
  set Subdivisions = $grid
end
subsection Load balancing
  set Balance at set-up = $at_setup
  set Repartition interval (steps) = $interval
end
subsection Shape functions
  set Family = $family
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $cells
    subsection Locking remedies
      $remedy
    end
  end
end
PRM
cd "$work"
for np in $ranks; do
  mpirun -np $np "$mpm" case.prm > log.$np
  echo "$variant, ranks $np, ${cells}^$dim block: $(sed -n 's/^  particles: //p' log.$np) particles"
  grep -E "time loop:|memory:|load balancing:" log.$np
done
rm -rf "$work"
