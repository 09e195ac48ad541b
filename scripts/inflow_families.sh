#!/usr/bin/env bash
# The pour into a box (prm/pour_into_box.prm, doc/guide/inflow.md) with
# each shape-function family, with domains kept inside the grid and cut
# at it (Domain outside the grid = clamp), to 0.6 s: whether the run
# finishes, and if not, when and why it stops.
# Usage: scripts/inflow_families.sh [RESULTS]   (MPM=...)
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
results=${1:-$root/results/inflow_families}
mkdir -p "$results"
echo "| family | domains outside the grid | result |"
echo "|---|---|---|"
for family in standard uGIMP cpGIMP CPDI CPDI2; do
  for outside in error clamp; do
    [ "$family" = standard ] && [ "$outside" = clamp ] && continue
    name="${family}_${outside}"
    cat > "$results/$name.prm" <<PRM
include $root/prm/pour_into_box.prm
subsection Shape functions
  set Family = $family
  set Domain outside the grid = $outside
end
subsection Time stepping
  set End time = 0.6
end
subsection Output
  set Directory = $results/$name
  set Write vtu = false
  set Write csv = false
end
PRM
    if "$mpm" "$results/$name.prm" > "$results/$name.log" 2>&1; then
      result="finishes"
    else
      result=$(grep -o "stopped at step [0-9]* (t = [0-9.e+-]*): .*" \
                 "$results/$name.log" | head -1 | cut -c1-160)
    fi
    echo "| $family | $outside | $result |"
  done
done
