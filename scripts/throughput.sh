#!/usr/bin/env bash
# BENCHMARKS.md section 10: particle-updates per second of the time loop and
# peak memory per particle, on 1 and 2 ranks, as printed by mpm itself.
# Usage: scripts/throughput.sh [cells]   (cells inside the block per
# direction: 256 or 512). Run it on an otherwise idle machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cells=${1:-256}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
cat > "$work/case.prm" <<PRM
include $root/prm/throughput_2d.prm
subsection Grid
  set Subdivisions = $((cells * 3 / 2))
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $cells
  end
end
PRM
cd "$work"
for np in 1 2; do
  mpirun -np $np "$root/build/mpm" case.prm > log.$np
  echo "ranks $np, ${cells}^2 block: $(sed -n 's/^  particles: //p' log.$np) particles"
  grep -E "time loop:|memory:" log.$np
done
rm -rf "$work"
