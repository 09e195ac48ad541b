#!/usr/bin/env bash
# The vibrating cantilever (prm/cantilever_newmark.prm) by the Newmark
# integrator: the period over the FE reference for standard MPM and the
# assumed-stress filter (mass and compliance metric) at 1, 2 and 4 cells
# through the depth at a step of 0.01 s, the compliance filter at 2
# cells over steps from 5 to 84 times the explicit stability limit, and
# uGIMP and CPDI (CPDI also with the compliance filter) at 2 cells.
# Writes OUT/table.txt: cells variant dt dt/limit T/T_FE energy change per
# period, Newton iterations per step, wall time. T_FE from the FE
# reference solver (build/mpm-fe prm/fe_cantilever_modal.prm). About 1 min.
# Usage: scripts/cantilever_newmark_study.sh [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
out=$(realpath -m "${1:-results/cantilever_newmark}")
mkdir -p "$out"
(cd "$out" && "$root/build/mpm-fe" "$root/prm/fe_cantilever_modal.prm" > fe_log.txt)
T_FE=$(awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
                { T = $c["T_1"] } END { print T }' \
       "$out/output-fe-cantilever/refinement_study.csv")
echo "T_FE = $T_FE s (mpm-fe)"
table="$out/table.txt"
echo "cells variant dt dt_over_limit T_over_T_FE energy_change_per_period newton_per_step wall_s" > "$table"
run() { # cells [FAMILY:]variant dt
  local n=$1 variant=$2 dt=$3 filter=none metric=mass family=standard
  case $variant in *:*) family=${variant%%:*} ;; esac
  case ${variant#*:} in
    filter-mass) filter="assumed stress" ;;
    filter-compliance) filter="assumed stress"; metric=compliance ;;
  esac
  local dir="$out/${n}_${variant/:/_}_$dt"
  cat > "$out/case.prm" <<PRM
include $root/prm/cantilever_newmark.prm
subsection Grid
  set Subdivisions = $((12 * n)), $((5 * n))
end
subsection Time stepping
  set Time step = $dt
end
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Output
  set Directory = $dir
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $((10 * n)), $n
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = $metric
    end
  end
end
PRM
  rm -rf "$dir"
  local start end
  start=$(date +%s.%N)
  "$mpm" "$out/case.prm" > "$out/log.txt"
  end=$(date +%s.%N)
  local ratio
  ratio=$(sed -n 's/.* = \([0-9.e+-]*\) times the explicit stability limit.*/\1/p' "$out/log.txt")
  /usr/bin/python3 - "$dir/statistics.txt" "$n" "$variant" "$dt" "$ratio" "$T_FE" "$start" "$end" <<'PY' | tee -a "$table"
import sys
import pandas as pd
f, n, variant, dt, ratio, T_FE, start, end = sys.argv[1:]
d = pd.read_csv(f, sep=r"\s+")
t, u = d.time.values, d.tip_displacement_y.values
E = (d.kinetic_energy + d.strain_energy).values
# upward zero crossings of the tip displacement (as scripts/beam_period.py)
up = [(t[i] - u[i] * (t[i + 1] - t[i]) / (u[i + 1] - u[i]), i)
      for i in range(len(t) - 1) if u[i] < 0 <= u[i + 1]]
periods = len(up) - 1
T = (up[-1][0] - up[0][0]) / periods
dE = (E[up[-1][1]] - E[up[0][1]]) / E[0] / periods
steps = (d.newton_iterations > 0).sum()
print("%s %s %s %.1f %.4f %+.4f %.2f %.1f" % (
    n, variant, dt, float(ratio), T / float(T_FE), dE,
    d.newton_iterations.sum() / max(steps, 1), float(end) - float(start)))
PY
}
for n in 1 2 4; do
  for v in standard filter-mass filter-compliance; do run $n $v 0.01; done
done
for dt in 0.0025 0.005 0.02 0.04; do run 2 filter-compliance $dt; done
for v in uGIMP:standard CPDI:standard CPDI:filter-compliance; do run 2 $v 0.01; done
