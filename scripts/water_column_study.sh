#!/usr/bin/env bash
# Water column collapse (doc/benchmarks/water_column.md,
# prm/water_column.prm; the experiment of Martin & Moyce 1952):
# runs the case with standard MPM and with the cell and node theta-bar
# (Volumetric smoothing = cell, node), one after the other on one core, keeps
# each run's output in OUT/<variant>/ and its screen output in
# OUT/<variant>.log, writes OUT/table.md (scripts/water_column_rms.py:
# RMS of Z and H against Martin & Moyce, checkerboard, largest speed, wall
# time) and the figure doc/figures/water_column.png (or $PLOT)
# (scripts/plot_water_column.py); if OUT holds runs of the grid studies
# below, also water_column_grids.png beside it.
# With the second argument "grid" it also runs standard MPM and the node
# theta-bar on h = a/10 (to the end) and h = a/40 (to t = 0.19 s, T = 3.5:
# the front data only; about 5 minutes) into OUT/standard_h10,
# OUT/standard_h40, OUT/theta-bar-node_h10, OUT/theta-bar-node_h40.
# With "fine" instead it runs the node theta-bar on h = a/80 (16 minutes
# of CPU on one core) and h = a/160 (94 minutes on 2 ranks on a machine
# shared with builds), to t = 0.19 s, for the front's grid convergence
# (doc/benchmarks/water_column.md); its table goes to OUT/table-fine.md.
# Variants: standard, theta-bar (Volumetric smoothing = cell) and
# theta-bar-node (= node), each with a suffix _h10, _h40, _h80 or _h160
# for another grid; VARIANTS="..." runs a subset; CFL=... another CFL
# number than the parameter file's 0.5. NP=2 runs every variant
# on 2 MPI ranks (the _h160 ones always run on 2). NEWMARK=<step> runs
# every variant by Integrator = Newmark at that step instead (doc/benchmarks/water_column.md:
# VARIANTS=theta-bar NEWMARK=0.001).
# Usage: scripts/water_column_study.sh [OUT] [grid|fine]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/water_column}")
variants=${VARIANTS:-standard theta-bar theta-bar-node}
[ "${2:-}" = grid ] &&
  variants="$variants standard_h10 standard_h40 theta-bar-node_h10 theta-bar-node_h40"
[ "${2:-}" = fine ] && variants="theta-bar-node_h80 theta-bar-node_h160"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
suffix=""
[ "${2:-}" = fine ] && suffix=-fine # its own table, beside the study's
times=$out/times$suffix.txt
: > "$times"
for variant in $variants; do
  case $variant in
    theta-bar-node*) smoothing=node ;;
    theta-bar*) smoothing=cell ;;
    *) smoothing=none ;;
  esac
  # cells per a (20 in the parameter file) and end time
  n=20; end=0.57
  case $variant in
    *_h10) n=10 ;;
    *_h40) n=40; end=0.19 ;;
    *_h80) n=80; end=0.19 ;;
    *_h160) n=160; end=0.19 ;;
  esac
  np=${NP:-1}
  case $variant in *_h160) np=2 ;; esac
  run=("$root/build/mpm")
  [ "$np" = 1 ] || run=(mpirun -np "$np" "$root/build/mpm")
  dir="$out/$variant"
  cat > "$out/$variant.prm" <<PRM
include $root/prm/water_column.prm
subsection Grid
  set Subdivisions = $((25 * n)), $((5 * n / 2))
end
subsection Time stepping
  set End time = $end
  ${CFL:+set CFL number = $CFL}
  ${NEWMARK:+set Integrator = Newmark}
  ${NEWMARK:+set Time step control = fixed}
  ${NEWMARK:+set Time step = $NEWMARK}
end
subsection Output
  set Directory = $dir
  set Write vtu = false
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $n, $((2 * n))
    subsection Locking remedies
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
  rm -rf "$dir"
  start=$(date +%s.%N)
  # a run that stops (status 2) keeps its output up to there: report it
  status=0
  "${run[@]}" "$out/$variant.prm" > "$out/$variant.log" 2>&1 || status=$?
  end=$(date +%s.%N)
  note=""
  [ $status = 0 ] || note=" (stopped, status $status: $(grep -o 'stopped at step.*' "$out/$variant.log" | head -1))"
  echo "$variant $(python3 -c "print(f'{$end - $start:.1f}')")$note" | tee -a "$times"
done
# c = sqrt(K/rho) of the parameter file
c=$(python3 -c "import math; print(math.sqrt(6.25e5/1000))")
{
  runs=""
  for variant in $variants; do runs="$runs $out/$variant"; done
  /usr/bin/python3 "$root/scripts/water_column_rms.py" --check-csv --c "$c" $runs
  echo
  echo "wall time [s] (whole run; one core, or 2 ranks with NP=2 and for _h160):"
  cat "$times"
} | tee "$out/table$suffix.md"
plot=${PLOT:-$root/doc/figures/water_column.png}
mkdir -p "$(dirname "$plot")"
/usr/bin/python3 "$root/scripts/plot_water_column.py" "$out" "$plot"
