#!/usr/bin/env bash
# Manufactured-solution convergence study
# (doc/benchmarks/manufactured_solution.md, prm/manufactured_solution.prm:
# u_i = G sin(pi X_i) sin(c pi t + phi_i) held by its body force): for every
# shape-function family and G = 1e-4 and 0.05, one period on h = 1/8, 1/16,
# 1/32, 1/64 (2D) or h = 1/4, 1/8 (--3d), dt = 0.2 h/c. Writes
#   OUT/errors.csv  dim,family,G,h,steps,u_L2_error,u_max_error,rate_L2,
#                   rate_max,u_L2_peak,u_max_peak (errors at t = T divided
#                   by G; rate = log2 of the ratio to the next coarser h;
#                   peak = the largest over the outputs, every T/20)
#   OUT/rates.csv   dim,family,G,ls_rate_L2,ls_rate_max (least-squares slope
#                   of log error against log h over the finest three grids;
#                   empty with fewer than three)
# and keeps each run's statistics and first and last particles in
# OUT/<dim>d_<family>_G<G>_n<cells>/. scripts/plot_mms.py plots errors.csv.
#
# Usage: scripts/mms_study.sh [--3d] [--families "standard uGIMP"] [OUT]
#   OUT        default results/mms (results/mms_3d with --3d)
#   --families space-separated list, default $FAMILIES or "standard"; values
#              standard, uGIMP, cpGIMP, CPDI, CPDI2 (Shape functions/Family;
#              the entry is written only for non-standard families, so the
#              study runs on builds that do not have it yet)
# Environment: MPM (the executable, default build/mpm), NP (MPI ranks,
# default 1), GS (default "1e-4 0.05"), NS (cells per direction, default
# "8 16 32 64", 3D "4 8").
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dim=2
families=${FAMILIES:-standard}
out=""
while [ $# -gt 0 ]; do
  case $1 in
    --3d) dim=3 ;;
    --families) families=$2; shift ;;
    -h|--help) sed -n '2,24p' "$0"; exit 0 ;;
    *) out=$1 ;;
  esac
  shift
done
if [ $dim = 3 ]; then
  base="$root/prm/manufactured_solution_3d.prm"
  ns=${NS:-4 8}
  out=$(realpath -m "${out:-results/mms_3d}")
else
  base="$root/prm/manufactured_solution.prm"
  ns=${NS:-8 16 32 64}
  out=$(realpath -m "${out:-results/mms}")
fi
gs=${GS:-1e-4 0.05}
mpm=${MPM:-$root/build/mpm}
np=${NP:-1}
run=("$mpm")
if [ "$np" -gt 1 ]; then
  # OpenMPI refuses to run as root unless told (CI, containers)
  export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  run=(mpirun -np "$np" "$mpm")
fi
# the physical constants of the benchmark file (only G varies here)
E=1e7; nu=0.3; rho=1000
c=$(awk -v E=$E -v r=$rho 'BEGIN{printf "%.17g", sqrt(E/r)}')
T=$(awk -v c="$c" 'BEGIN{printf "%.17g", 2/c}')

mkdir -p "$out"
csv="$out/errors.csv"
echo "dim,family,G,h,steps,u_L2_error,u_max_error,rate_L2,rate_max,u_L2_peak,u_max_peak" > "$csv"
start=$(date +%s)
for family in $families; do
  for G in $gs; do
    prev_l2=""; prev_max=""
    for n in $ns; do
      h=$(awk -v n="$n" 'BEGIN{printf "%.17g", 1/n}')
      dt=$(awk -v n="$n" -v c="$c" 'BEGIN{printf "%.17g", 0.2/(n*c)}')
      dir="$out/${dim}d_${family}_G${G}_n${n}"
      shape=""
      if [ "$family" != standard ]; then
        shape=$'subsection Shape functions\n  set Family = '"$family"$'\n  set Domain outside the grid = clamp\nend'
      fi
      rm -rf "$dir"
      mkdir -p "$dir"
      cat > "$dir/case.prm" <<PRM
include $base
set Constants = G=$G, E=$E, nu=$nu, rho=$rho
subsection Grid
  set Subdivisions = $n
end
subsection Time stepping
  set End time = $T
  set Time step = $dt
end
subsection Output
  set Directory = $dir
  set Interval = $(awk -v T="$T" 'BEGIN{printf "%.17g", T/20}')
  set Write vtu = false
  set Write csv = true
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $n
  end
end
$shape
PRM
      if "${run[@]}" "$dir/case.prm" > "$dir/log.txt" 2>&1; then
        read -r steps l2 mx < <(tail -1 "$dir/statistics.txt" |
                                awk '{print $2, $(NF-1), $NF}')
        peaks=$(awk 'NR > 1 { if ($(NF-1) > a) a = $(NF-1); if ($NF > b) b = $NF }
                     END { print a "," b }' "$dir/statistics.txt")
        # the particle tables in between are not needed: keep t = 0 and T
        ls "$dir"/particles-*.csv | sed '1d;$d' | xargs -r rm
        rates=$(awk -v a="$prev_l2" -v b="$l2" -v c="$prev_max" -v d="$mx" \
          'BEGIN{ if (a == "") print ","; else
                  printf "%.3f,%.3f", log(a/b)/log(2), log(c/d)/log(2) }')
        prev_l2=$l2; prev_max=$mx
        echo "$dim,$family,$G,$h,$steps,$l2,$mx,$rates,$peaks" | tee -a "$csv"
      else
        # a failed run is a result too: keep going, say why
        echo "$dim,$family,$G,$h,,failed,failed,,,," | tee -a "$csv"
        grep 'mpm:' "$dir/log.txt" | tail -1 || true
        prev_l2=""; prev_max=""
      fi
    done
  done
done

# least-squares rates over the finest three grids of each family and G
awk -F, 'NR > 1 && $6 != "failed" {
    key = $1 "," $2 "," $3; k = ++n[key]
    x[key, k] = log($4); y2[key, k] = log($6); ym[key, k] = log($7)
    if (!(key in order)) { order[key] = ++m; keys[m] = key } }
  function slope(key, y,    i, k0, sx, sy, sxx, sxy, nn) {
    k0 = n[key] - 2; nn = 3
    for (i = k0; i <= n[key]; ++i) {
      sx += x[key, i]; sy += y[key, i]
      sxx += x[key, i] * x[key, i]; sxy += x[key, i] * y[key, i] }
    return (nn * sxy - sx * sy) / (nn * sxx - sx * sx) }
  END { print "dim,family,G,ls_rate_L2,ls_rate_max"
    for (j = 1; j <= m; ++j) { key = keys[j]
      if (n[key] >= 3) printf "%s,%.3f,%.3f\n", key, slope(key, y2), slope(key, ym)
      else print key ",," } }' "$csv" > "$out/rates.csv"
cat "$out/rates.csv"
echo "wall time: $(( $(date +%s) - start )) s" | tee "$out/time.txt"
