#!/usr/bin/env bash
# BENCHMARKS.md section 10: particle-updates per second of the time loop and
# peak memory per particle, on 1 and 2 ranks. Usage: scripts/throughput.sh [cells]
# (cells inside the block per direction; 256 or 512). Run on an idle machine.
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
  /usr/bin/time -v mpirun -np $np "$root/build/mpm" case.prm > log.$np 2> time.$np
  n=$(sed -n 's/^  particles: //p' log.$np)
  loop=$(awk -F'|' '/G2P|P2G|grid update|MUSL re-map|position update|stress update/ {gsub(/s/,"",$4); t+=$4} END {print t}' log.$np)
  rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' time.$np)
  awk -v n="$n" -v t="$loop" -v rss="$rss" -v np="$np" 'BEGIN {
    printf "ranks %d: %d particles, 100 steps, time loop %.2f s: %.2f M particle-updates/s; peak RSS %.0f MB (%.2f KB/particle, rank 0 process)\n",
      np, n, t, n*100/t/1e6, rss/1024, rss/n }'
done
