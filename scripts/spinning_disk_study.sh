#!/usr/bin/env bash
# Spinning disk (doc/benchmarks/spinning_disk.md; prm/spinning_disk.prm: a
# plane-stress disk, a = 1 m, omega = 1 rad/s, in its steady rotating state)
# for every shape-function family, with and without the assumed-stress filter:
# the error table at the end time and the seed-style panels (particles coloured
# by sigma_rr and sigma_rt, one panel per variant).
# Usage: scripts/spinning_disk_study.sh [OUT]   (default results/spinning_disk)
# A variant is a family with optional suffixes: +filter (assumed-stress
# filter), +enriched (the filter with Filter field = enriched), +force (the
# filter with Filtered stress = force only), +APIC (Velocity transfer =
# APIC), +midpoint (Strain increment = midpoint), +leapfrog (Leapfrog
# start = true) and +still (the disk does not turn: held by the equivalent
# centrifugal body force omega^2 x, so no particle crosses a cell), e.g.
# CPDI+filter+force+APIC+midpoint+leapfrog. The table gives the measures at
# the end time and the largest RMS errors over all outputs (set INTERVAL).
# Environment: END (end time, default 6.2), CELLS (grid cells per direction
# over [-1.25,1.25], default 50: h = 0.05), CFL (default 0.5), SCHEME
# (Time stepping/Scheme, default MUSL), VARIANTS
# (default below), NP (MPI ranks per run, default 1), JOBS (runs at the same
# time, default 1), REFINEMENTS (refinements of the disk's body mesh,
# default that of prm/spinning_disk.prm, 4: 12 288 particles; 3 gives
# 3 072), VTU (true: also write ParaView files, default false), INTERVAL
# (output interval, default END), CSV (false: no particle tables, default
# true), CONSTANTS (the file's Constants line, e.g. "a=1, omega=4, E=1e6,
# nu=0.49, rho=1000"; default that of prm/spinning_disk.prm), MPM
# (executable), PLOT (the PNG, default
# doc/figures/spinning_disk_variants.png; PLOT=none skips the picture).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/spinning_disk}
end=${END:-6.2}
cells=${CELLS:-50}
np=${NP:-1}
jobs=${JOBS:-1}
mpm=${MPM:-$root/build/mpm}
cfl=${CFL:-0.5}
scheme=${SCHEME:-MUSL}
vtu=${VTU:-false}
interval=${INTERVAL:-$end}
csv=${CSV:-true}
constants=""
[ -n "${CONSTANTS:-}" ] && constants="set Constants = $CONSTANTS"
refinements=""
[ -n "${REFINEMENTS:-}" ] && refinements="set Refinements = $REFINEMENTS"
plot=${PLOT:-$root/doc/figures/spinning_disk_variants.png}
variants=${VARIANTS:-"standard standard+filter uGIMP cpGIMP CPDI CPDI+filter CPDI2 CPDI2+filter CPDI+APIC CPDI+filter+APIC"}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# Open MPI binds rank 0 of every mpirun to the same core: runs side by side
# must not be bound.
bind=""
[ "$jobs" -gt 1 ] && bind="--bind-to none"
mkdir -p "$out"
table="$out/errors.csv"
h=$(awk -v n="$cells" 'BEGIN{print 2.5/n}')

# Runs one variant in $out/<variant>/ and writes its table row to
# $out/<variant>/row.csv.
run_variant() {
  local v=$1
  local family=${v%%+*}
  local filter="" transfer=FLIP field=Pian-Sumihara target="written back"
  local increment="start of step" leapfrog=false still=""
  case "$v" in *+filter*|*+enriched*) filter="set Stress filter = assumed stress" ;; esac
  case "$v" in *+force*) target="force only" ;; esac
  case "$v" in *+enriched*) field=enriched ;; esac
  case "$v" in *+APIC*) transfer=APIC ;; esac
  case "$v" in *+midpoint*) increment=midpoint ;; esac
  case "$v" in *+leapfrog*) leapfrog=true ;; esac
  case "$v" in *+still*) still="set Initial velocity = 0; 0
    set Body force = omega^2*x; omega^2*y" ;; esac
  local dir="$out/$v"
  rm -rf "$dir"; mkdir -p "$dir"
  cat > "$dir/case.prm" <<PRM
include $root/prm/spinning_disk.prm
$constants
subsection Grid
  set Subdivisions = $cells
end
subsection Shape functions
  set Family = $family
end
subsection Time stepping
  set End time = $end
  set CFL number = $cfl
  set Scheme = $scheme
  set Velocity transfer = $transfer
  set Leapfrog start = $leapfrog
end
subsection Output
  set Directory = $dir/output
  set Interval = $interval
  set Write vtu = $vtu
  set Write csv = $csv
end
subsection Bodies
  subsection Body 0
    $refinements
    $still
    subsection Material
      subsection Linear elastic
        set Strain increment = $increment
      end
    end
    subsection Locking remedies
      $filter
      set Filter field = $field
      set Filtered stress = $target
    end
  end
end
PRM
  local t0
  t0=$(date +%s)
  if ! mpirun -np "$np" $bind "$mpm" "$dir/case.prm" > "$dir/log.txt" 2>&1; then
    echo "$v failed: $(grep -m1 'mpm:' "$dir/log.txt")" >&2
    echo "$v,$h,$cfl,failed,,,,,,,,$(( $(date +%s) - t0 ))" > "$dir/row.csv"
    return 0
  fi
  local wall=$(( $(date +%s) - t0 ))
  awk -v v="$v" -v h="$h" -v cfl="$cfl" -v w="$wall" '
    NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
    NR == 2 { L0 = $c["angular_momentum_z"]; E0 = $c["total_energy"] }
    {
      last = $0
      if ($c["sigma_rr_rms_error"] > rr) rr = $c["sigma_rr_rms_error"]
      if ($c["sigma_rt_rms"] > rt) rt = $c["sigma_rt_rms"]
    }
    END {
      split(last, f, " ")
      # a disk held still has no angular momentum to compare with
      dL = L0 != 0 ? f[c["angular_momentum_z"]] / L0 - 1 : 0
      printf "%s,%s,%s,%s,%.4g,%.4g,%.4g,%.3g,%.3g,%.4g,%.4g,%s\n", v, h, cfl, f[c["time"]],
        f[c["sigma_rr_rms_error"]], f[c["sigma_rt_rms"]], f[c["v_r_rms"]],
        dL, f[c["total_energy"]] / E0 - 1, rr, rt, w
    }' "$dir/output/statistics.txt" > "$dir/row.csv"
}

start=$(date +%s)
# at most $jobs runs at a time (xargs -P); each prints its row when it ends
export -f run_variant
export root out cells end cfl scheme interval vtu csv constants refinements np mpm h bind
printf '%s\n' $variants |
  xargs -P "$jobs" -I{} bash -c 'run_variant "$1"; cat "$out/$1/row.csv"' _ {}
echo "variant,h,cfl,t,sigma_rr_rms_error,sigma_rt_rms,v_r_rms,angular_momentum_change,energy_change,sigma_rr_max,sigma_rt_max,wall_s" > "$table"
for v in $variants; do cat "$out/$v/row.csv" >> "$table"; done
echo "wall time: $(( $(date +%s) - start )) s"
[ "$plot" = none ] ||
  /usr/bin/python3 "$root/scripts/plot_spinning_disk_variants.py" "$out" "$plot" $variants
