#!/usr/bin/env bash
# Vibrating cantilever (doc/benchmarks/cantilever.md; prm/cantilever_beam.prm:
# L = 1 m, H = 0.1 m, clamped at x = 0, started in its first Euler-Bernoulli
# mode): the period for standard MPM and the assumed-stress filter (both
# metrics) at 1, 2 and 4 cells through the depth with 2x2 particles per cell,
# plus standard and compliance filter with 3x3 and 4x4 particles, and the
# enriched filter field, uGIMP and CPDI (with the enriched compliance filter)
# at 1, 2, 4 cells.
# Writes OUT/table.txt: cells ppc variant T T/T_EB T/T_Timoshenko T/T_FE,
# T_FE from the FE reference solver (build/mpm-fe prm/fe_cantilever_modal.prm,
# refined until the period changes by less than 0.1%; run first, ~10 s).
# A variant is [FAMILY:]standard|filter-mass|filter-compliance[-enriched].
# About 4 min on 2 cores.
# Usage: scripts/cantilever_study.sh [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/cantilever}")
mkdir -p "$out"
T_Ti=$("$root/scripts/timoshenko_period.py" | sed 's/.*T_Timoshenko = \([0-9.]*\).*/\1/')
(cd "$out" && "$root/build/mpm-fe" "$root/prm/fe_cantilever_modal.prm" > fe_log.txt)
T_FE=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
                { T = $c["T_1"] } END { print T }' \
       "$out/output-fe-cantilever/refinement_study.csv")
echo "T_FE = $T_FE s (mpm-fe), T_Timoshenko = $T_Ti s"
table="$out/table.txt"
echo "cells ppc variant T T/T_EB T/T_Timoshenko T/T_FE" > "$table"
run() { # cells ppc variant
  local n=$1 ppc=$2 variant=$3 filter=none metric=mass family=standard
  local field=Pian-Sumihara base=${3#*:}
  [ "$base" != "$variant" ] && family=${variant%%:*}
  case $base in *-enriched) field=enriched; base=${base%-enriched} ;; esac
  case $base in
    filter-mass) filter="assumed stress" ;;
    filter-compliance) filter="assumed stress"; metric=compliance ;;
  esac
  local dir="$out/${n}_${ppc}_${variant/:/_}"
  cat > "$out/case.prm" <<PRM
include $root/prm/cantilever_beam.prm
subsection Grid
  set Subdivisions = $((12 * n)), $((5 * n))
end
subsection Output
  set Directory = $dir
end
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $((10 * n)), $n
    set Particles per direction = $ppc
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = $metric
      set Filter field = $field
    end
  end
end
PRM
  rm -rf "$dir"
  "$root/build/mpm" "$out/case.prm" > "$out/log.txt"
  local T
  T=$("$root/scripts/beam_period.py" "$dir" | sed 's/^T = \([0-9.]*\) s.*/\1/')
  python3 -c "
T=$T; T_EB=2*3.141592653589793/(3.51602*(1e7*0.1**3/12/(1000*0.1))**0.5)
print('$n $ppc $variant %.5f %.4f %.4f %.4f' % (T, T/T_EB, T/$T_Ti, T/$T_FE))" | tee -a "$table"
}
for n in 1 2 4; do
  for v in standard filter-mass filter-compliance; do run $n 2 $v; done
done
for n in 1 2 4; do
  for v in filter-compliance-enriched uGIMP:standard CPDI:standard CPDI:filter-compliance-enriched; do
    run $n 2 $v
  done
done
for ppc in 3 4; do
  for n in 1 2; do
    for v in standard filter-compliance; do run $n $ppc $v; done
  done
done
