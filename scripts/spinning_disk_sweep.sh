#!/usr/bin/env bash
# Spinning disk over many turns (doc/benchmarks/spinning_disk.md): one method
# swept over the spin omega, Poisson's ratio nu, the grid and the number of
# turns. Writes OUT/sweep.csv (one row per run: the largest RMS errors of
# sigma_rr and sigma_rt over the first turn and over all turns, their values
# at the end, and the drift of angular momentum and energy per turn) and
# OUT/history.png (the error history of every run against the turn number).
# Usage: scripts/spinning_disk_sweep.sh [OUT]   (default results/spinning_disk_sweep)
# Environment (lists are space-separated; every combination is run):
#   OMEGAS (rad/s, default "0.25 1 4"), NUS (default "0 0.3 0.49"),
#   CELLS (grid cells per direction over [-1.25, 1.25], default "50": h = 0.05;
#     each grid gets a body mesh with about 2 particles per cell and
#     direction: 50 -> Refinements 4, 100 -> 5),
#   TURNS (default 1), CFL (default 0.5), FAMILY (default CPDI),
#   TRANSFER (FLIP | APIC, default APIC), INCREMENT (Strain increment:
#     "start of step" | midpoint, default midpoint), LEAPFROG (true | false,
#     default true), FILTER (none | written | force, default none: the
#     assumed-stress filter written back or on the force only), JOBS (runs
#     at the same time, default 2), MPM (executable), PLOT (the PNG, default
#     OUT/history.png; none skips it).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/spinning_disk_sweep}
omegas=${OMEGAS:-"0.25 1 4"}
nus=${NUS:-"0 0.3 0.49"}
cells_list=${CELLS:-50}
turns=${TURNS:-1}
cfl=${CFL:-0.5}
family=${FAMILY:-CPDI}
transfer=${TRANSFER:-APIC}
increment=${INCREMENT:-midpoint}
leapfrog=${LEAPFROG:-true}
filter=${FILTER:-none}
jobs=${JOBS:-2}
mpm=${MPM:-$root/build/mpm}
plot=${PLOT:-$out/history.png}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"

# The method as a variant of scripts/spinning_disk_study.sh, which writes
# and runs every case.
variant=$family
[ "$transfer" = APIC ] && variant+="+APIC"
[ "$increment" = midpoint ] && variant+="+midpoint"
[ "$leapfrog" = true ] && variant+="+leapfrog"
case "$filter" in
  written) variant+="+filter" ;;
  force) variant+="+filter+force" ;;
esac

# Runs one (omega, nu, cells) case in $out/w<omega>_nu<nu>_n<cells>/ and
# writes its row.csv.
run_case() {
  local omega=$1 nu=$2 cells=$3
  local dir="$out/w${omega}_nu${nu}_n${cells}"
  local refinements=$(awk -v n="$cells" 'BEGIN{r = 4; while (n > 50 * 2^(r - 4) * 1.5) ++r; print r}')
  local period end interval
  period=$(awk -v w="$omega" 'BEGIN{printf "%.12g", 2 * 3.141592653589793 / w}')
  end=$(awk -v p="$period" -v n="$turns" 'BEGIN{printf "%.12g", p * n}')
  interval=$(awk -v p="$period" 'BEGIN{printf "%.12g", p / 40}')
  rm -rf "$dir"
  local t0=$(date +%s)
  CONSTANTS="a=1, omega=$omega, E=1e6, nu=$nu, rho=1000" END=$end INTERVAL=$interval \
    CELLS=$cells REFINEMENTS=$refinements CFL=$cfl CSV=false VARIANTS=$variant \
    NP=1 JOBS=$jobs PLOT=none MPM=$mpm "$root/scripts/spinning_disk_study.sh" "$dir" > /dev/null
  local statistics="$dir/$variant/output/statistics.txt"
  if grep -q ',failed,' "$dir/$variant/row.csv"; then
    echo "$omega,$nu,$cells,failed" > "$dir/row.csv"
    echo "omega=$omega nu=$nu cells=$cells failed: $(grep -m1 'mpm:' "$dir/$variant/log.txt")" >&2
    return 0
  fi
  local wall=$(( $(date +%s) - t0 ))
  awk -v w="$omega" -v nu="$nu" -v n="$cells" -v p="$period" -v wall="$wall" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    NR == 2 { L0 = $c["angular_momentum_z"]; E0 = $c["total_energy"] }
    {
      t = $c["time"]; rr = $c["sigma_rr_rms_error"]; rt = $c["sigma_rt_rms"]
      if (t <= p * (1 + 1e-9)) { rr1 = rr > rr1 ? rr : rr1; rt1 = rt > rt1 ? rt : rt1 }
      rrmax = rr > rrmax ? rr : rrmax; rtmax = rt > rtmax ? rt : rtmax
      last_t = t; last_rr = rr; last_rt = rt
      dL = $c["angular_momentum_z"] / L0 - 1; dE = $c["total_energy"] / E0 - 1
    }
    END {
      turns = last_t / p
      printf "%s,%s,%s,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.3g,%.3g,%s\n", w, nu, n,
        turns, rr1, rt1, rrmax, rtmax, last_rr, last_rt, dL / turns, dE / turns, wall
    }' "$statistics" > "$dir/row.csv"
}

start=$(date +%s)
export -f run_case
export root out turns cfl variant jobs mpm
for omega in $omegas; do for nu in $nus; do for cells in $cells_list; do
  echo "$omega $nu $cells"
done; done; done |
  xargs -P "$jobs" -L1 bash -c 'run_case "$1" "$2" "$3"; cat "$out/w$1_nu$2_n$3/row.csv"' _
table="$out/sweep.csv"
echo "# variant=$variant cfl=$cfl" > "$table"
echo "omega,nu,cells,turns,sigma_rr_max_turn1,sigma_rt_max_turn1,sigma_rr_max,sigma_rt_max,sigma_rr_end,sigma_rt_end,angular_momentum_per_turn,energy_per_turn,wall_s" >> "$table"
for omega in $omegas; do for nu in $nus; do for cells in $cells_list; do
  cat "$out/w${omega}_nu${nu}_n${cells}/row.csv" >> "$table"
done; done; done
echo "wall time: $(( $(date +%s) - start )) s; table: $table"
[ "$plot" = none ] ||
  /usr/bin/python3 "$root/scripts/plot_spinning_disk_history.py" "$out" "$plot"
