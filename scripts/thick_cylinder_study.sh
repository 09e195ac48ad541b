#!/usr/bin/env bash
# Thick-walled cylinder under internal pressure (prm/thick_cylinder.prm):
# every locking remedy for nu = 0.3, 0.49, 0.499, 0.4999 on background grids
# h = 0.125 and 0.0625 (body mesh of the same size, 3x3 particles per body
# cell, scripts/make_quarter_annulus.py). Writes OUT/table.txt (the
# benchmark's columns at t = 0.8 s: u_r(inner)/exact, pressure and sigma_rr
# errors and checkerboard, divided by p) and keeps each run's output in
# OUT/<nu>_<h>_<variant>/ (statistics and the final particles) for
# scripts/plot_thick_cylinder.py.
# Usage: scripts/thick_cylinder_study.sh [OUT] [h values...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/thick_cylinder}")
shift || true
hs=${*:-0.125 0.0625}
mkdir -p "$out"
table="$out/table.txt"
echo "nu h variant ur_inner_ratio pressure_error sigma_rr_error checkerboard" > "$table"
start=$(date +%s)
for h in $hs; do
  nx=$(python3 -c "print(round(2.5/$h))")
  nr=$(python3 -c "print(round(1/$h))")
  # body cells about square at the mid radius
  nt=$(python3 -c "import math; print(round(math.pi/4*3/$h))")
  mesh="$out/quarter_annulus_${nr}x${nt}.ucd"
  "$root/scripts/make_quarter_annulus.py" "$mesh" 1 2 $nr $nt
  for nu in 0.3 0.49 0.499 0.4999; do
    for variant in standard theta-bar node-average filter filter+theta-bar; do
      filter=none; smoothing=none
      case $variant in
        theta-bar) smoothing=cell ;;
        node-average) smoothing=node ;;
        filter) filter="assumed stress" ;;
        filter+theta-bar) filter="assumed stress"; smoothing=cell ;;
      esac
      dir="$out/${nu}_${h}_${variant}"
      cat > "$out/case.prm" <<PRM
include $root/prm/thick_cylinder.prm
set Constants = a=1, b=2, p=1e3, E=1e6, nu=$nu, rho=1000, tr=0.2
subsection Grid
  set Subdivisions = $nx
end
subsection Output
  set Directory = $dir
  set Interval = 0.1
  set Write vtu = false
  set Write csv = true
end
subsection Bodies
  subsection Body 0
    set Mesh file = $mesh
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = compliance
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
      rm -rf "$dir"
      if "$root/build/mpm" "$out/case.prm" > "$dir.log" 2>&1; then
        echo "$nu $h $variant $(tail -1 "$dir/statistics.txt" | awk '{print $(NF-3), $(NF-2), $(NF-1), $NF}')" | tee -a "$table"
      else
        # an unstable run is a result too: keep going, say why in the log
        echo "$nu $h $variant failed failed failed failed" | tee -a "$table"
        grep 'mpm:' "$dir.log" | tail -1
      fi
    done
  done
done
echo "wall time: $(( $(date +%s) - start )) s" | tee "$out/time.txt"
