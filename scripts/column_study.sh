#!/usr/bin/env bash
# Self-weight column (doc/benchmarks/self_weight_column.md;
# prm/self_weight_column.prm: a laterally confined column, H = 10 m, plane
# strain, under gravity; exact sigma_yy = -rho g (H - Y)): every variant for
# nu = 0.3, 0.49, 0.499 and h = 1, 0.5, 0.25, on the aligned grid of the
# definition and on a distorted grid (scripts/make_distorted_grid.py, nodes
# moved by up to 0.2 h). Writes OUT/table.txt (the errors at t = 3 s,
# divided by rho g H) and keeps each run's output in
# OUT/<grid>_<nu>_<h>_<variant>/ for scripts/plot_column.py.
# Usage: scripts/column_study.sh [OUT] [h values...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/column}")
shift || true
hs=${*:-1 0.5 0.25}
mkdir -p "$out"
table="$out/table.txt"
echo "grid nu h variant sigma_yy_error pressure_error checkerboard" > "$table"
for grid in aligned distorted; do
for nu in 0.3 0.49 0.499; do
  for h in $hs; do
    nx=$(python3 -c "print(round(1/$h))")
    ny=$(python3 -c "print(round(11/$h))")
    if [ $grid = distorted ]; then
      "$root/scripts/make_distorted_grid.py" "$out/grid_$h.ucd" 1 11 $nx $ny 0.2
      grid_prm="set Type = mesh file
  set Mesh file = $out/grid_$h.ucd"
      slip="set Slip boundary ids = 0"
    else
      grid_prm="set Subdivisions = $nx, $ny"
      slip="set Slip boundary ids = 0, 1, 2"
    fi
    for variant in standard theta-bar node-average filter filter+theta-bar; do
      filter=none; smoothing=none
      case $variant in
        theta-bar) smoothing=cell ;;
        node-average) smoothing=node ;;
        filter) filter="assumed stress" ;;
        filter+theta-bar) filter="assumed stress"; smoothing=cell ;;
      esac
      dir="$out/${grid}_${nu}_${h}_${variant}"
      cat > "$out/case.prm" <<PRM
include $root/prm/self_weight_column.prm
set Constants = H=10, E=1e6, nu=$nu, rho=80, g=10, tr=1
subsection Grid
  $grid_prm
end
subsection Boundary conditions
  $slip
end
subsection Output
  set Directory = $dir
  set Interval = 0.5
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $nx, $(python3 -c "print(round(10/$h))")
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = compliance
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
      rm -rf "$dir"
      "$root/build/mpm" "$out/case.prm" > "$out/log.txt"
      echo "$grid $nu $h $variant $(tail -1 "$dir/statistics.txt" | awk '{print $(NF-2), $(NF-1), $NF}')" | tee -a "$table"
    done
  done
done
done
