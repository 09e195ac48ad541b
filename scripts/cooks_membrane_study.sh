#!/usr/bin/env bash
# Cook's membrane (doc/benchmarks/cooks_membrane.md; prm/cooks_membrane.prm and
# prm/cooks_membrane_plane_strain.prm): (a) plane stress and (b) plane
# strain at nu = 0.4999, every variant (standard; assumed-stress filter
# with the mass and the compliance metric; theta-bar; compliance filter +
# theta-bar; CPDI; CPDI + compliance filter) on background grids
# h = 4 and 2 (body mesh: the panel in (48/h)^2 cells, 2x2 particles each).
# Writes OUT/table.csv (the benchmark's columns at the end time: the fitted
# u_y at (48,60) and (48,52), their ratios to the FE reference, the ratio of
# the particle nearest the corner, and the change of corner_ratio over the
# last tenth of the run, which shows how far the damped approach is from
# static) and keeps each run's output in OUT/<case>_<h>_<variant>/
# (statistics and the final particles) for scripts/plot_cooks_membrane.py.
# The fit radius r_fit of the point displacements is set to h.
# Usage: scripts/cooks_membrane_study.sh [OUT] [h values...]
# CASES="a" and VARIANTS="standard theta-bar" restrict the runs (default:
# both cases, every variant); the table is then appended to, not replaced.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/cooks_membrane}")
shift || true
hs=${*:-4 2}
mkdir -p "$out"
table="$out/table.csv"
all_variants="standard filter-mass filter-compliance theta-bar filter+theta-bar cpdi cpdi+filter"
if [ -z "${CASES:-}${VARIANTS:-}" ] || [ ! -f "$table" ]; then
  echo "case,h,variant,uy_corner,uy_mid,corner_ratio,mid_ratio,corner_nearest_ratio,last_change,steps,wall_s" > "$table"
fi
start=$(date +%s)
for case in ${CASES:-a b}; do
  base=$root/prm/cooks_membrane.prm
  [ $case = b ] && base=$root/prm/cooks_membrane_plane_strain.prm
  for h in $hs; do
    nx=$(python3 -c "print(round(52/$h))")
    ny=$(python3 -c "print(round(68/$h))")
    nb=$(python3 -c "print(round(48/$h))")
    for variant in ${VARIANTS:-$all_variants}; do
      filter=none; metric=compliance; smoothing=none; family=standard
      case $variant in
        filter-mass) filter="assumed stress"; metric=mass ;;
        filter-compliance) filter="assumed stress" ;;
        theta-bar) smoothing=cell ;;
        filter+theta-bar) filter="assumed stress"; smoothing=cell ;;
        cpdi) family=CPDI ;;
        cpdi+filter) family=CPDI; filter="assumed stress" ;;
      esac
      dir="$out/${case}_${h}_${variant}"
      end_time=$(sed -n 's/^ *set End time = //p' "$base" | tail -1)
      # the fit radius of the point displacement is the grid spacing
      constants=$(grep '^set Constants' "$base" | tail -1 |
                  sed "s/r_fit=[^,]*/r_fit=$h/")
      cat > "$out/case.prm" <<PRM
include $base
$constants
subsection Grid
  set Subdivisions = $nx, $ny
end
subsection Time stepping
  set End time = $end_time
end
subsection Shape functions
  set Family = $family
end
subsection Output
  set Directory = $dir
  set Interval = $(python3 -c "print($end_time/10)")
  set Write vtu = false
  set Write csv = true
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $nb
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = $metric
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
      rm -rf "$dir"
      t0=$(date +%s.%N)
      if "$root/build/mpm" "$out/case.prm" > "$dir.log" 2>&1; then
        wall=$(python3 -c "import time; print(round(time.time() - $t0, 1))")
        row=$(tail -2 "$dir/statistics.txt" | awk -v OFS=, '
          NR == 1 { prev = $(NF-2) }
          NR == 2 { d = $(NF-2) - prev; if (d < 0) d = -d;
                    print $(NF-4), $(NF-3), $(NF-2), $(NF-1), $NF, d, $2 }')
        echo "$case,$h,$variant,$row,$wall" | tee -a "$table"
      else
        # an unstable run is a result too: keep going, say why in the log
        echo "$case,$h,$variant,failed,failed,failed,failed,failed,failed,0,0" | tee -a "$table"
        grep 'mpm:' "$dir.log" | tail -1 || true
      fi
    done
  done
done
echo "wall time (cases ${CASES:-a b}, h $hs): $(( $(date +%s) - start )) s" | tee -a "$out/time.txt"
