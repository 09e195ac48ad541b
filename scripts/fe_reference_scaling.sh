#!/usr/bin/env bash
# How mpm-fe's distributed path (Linear solver/Method = AMG) scales: for
# each case and number of processes, the unknowns, the Krylov iterations
# with AMG, the wall times of assembly, AMG set-up and solve, the whole
# run's wall time and the peak memory of the processes together.
# Cases:
#   cantilever-3d  prm/fe_cantilever_3d.prm, Q2 displacement, CG: 10 x 1 x 1
#                  cells refined 1 to 4 times (3 k to 1.05 M unknowns)
#   cook-mixed     prm/fe_cooks_membrane_plane_strain.prm, Taylor-Hood
#                  Q2/Q1 at nu = 0.4999 (or NU), MINRES: 2 x 2 cells
#                  refined 3 to 6 times (2.5 k to 149 k unknowns)
# Usage: [CASES="cantilever-3d cook-mixed"] [RANKS="1 2"] [NU=0.4999]
#        [REFINEMENTS_cantilever_3d="1 2 3 4"] [REFINEMENTS_cook_mixed=...]
#        scripts/fe_reference_scaling.sh
# About 4 minutes on 2 cores; the 1 M-unknown run needs about 6 GB.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
fe=${MPM_FE:-$root/build/mpm-fe}
cases=${CASES:-cantilever-3d cook-mixed}
ranks_list=${RANKS:-1 2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

prm_of() {
  case $1 in
    cantilever-3d) echo "$root/prm/fe_cantilever_3d.prm" ;;
    cook-mixed) echo "$root/prm/fe_cooks_membrane_plane_strain.prm" ;;
    *) echo "unknown case '$1'" >&2; exit 1 ;;
  esac
}
refinements_of() {
  case $1 in
    cantilever-3d) echo "${REFINEMENTS_cantilever_3d:-1 2 3 4}" ;;
    cook-mixed) echo "${REFINEMENTS_cook_mixed:-3 4 5 6}" ;;
  esac
}

printf '%-14s %5s %4s %10s %6s %10s %10s %10s %9s %9s %14s\n' \
  case ranks refs unknowns iters assembly_s amg_set_s solve_s run_s \
  memory_MB quantity
for c in $cases; do
  for r in $(refinements_of "$c"); do
    for np in $ranks_list; do
      {
        sed "s/nu=0.4999/nu=${NU:-0.4999}/" "$(prm_of "$c")"
        cat <<PRM
subsection Discretisation
  set Refinements = $r
end
subsection Linear solver
  set Method = AMG
end
subsection Output
  set Directory = $work/out
  set Write vtu = false
end
PRM
      } > "$work/case.prm"
      start=$(date +%s.%N)
      /usr/bin/time -f '%M' -o "$work/rss" \
        mpirun -np "$np" "$fe" "$work/case.prm" > "$work/log" 2>&1 \
        || { cat "$work/log"; exit 1; }
      end=$(date +%s.%N)
      # the largest process's peak times the processes: an upper bound
      rss=$(cat "$work/rss")
      /usr/bin/python3 - "$c" "$np" "$r" "$start" "$end" "$rss" \
        "$work/out/refinement_study.csv" <<'PY'
import csv, sys
case, np, r, start, end, rss, table = sys.argv[1:]
v = list(csv.DictReader(open(table)))[-1]
print('%-14s %5s %4s %10s %6s %10.2f %10.2f %10.2f %9.1f %9.0f %14.8e' % (
    case, np, r, v['dofs'], v['linear_iterations'],
    float(v['assembly_seconds']), float(v['amg_setup_seconds']),
    float(v['solve_seconds']), float(end) - float(start),
    int(np) * float(rss) / 1024, float(v['quantity'])))
PY
    done
  done
done
