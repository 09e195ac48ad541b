#!/usr/bin/env bash
# The validation suite: one command that regenerates every result and
# figure of the benchmark pages (doc/benchmarks/, one page each) and of
# doc/fe_reference.md, then recomputes the
# benchmark measures of every run that kept particle CSV files
# (scripts/recompute_measures.py) and writes a summary with the wall time
# of each part to results/validation/summary.txt.
#
# Usage: scripts/validation_suite.sh          # the full suite
#        QUICK=1 scripts/validation_suite.sh  # a coarse, short smoke run
#        PARTS="fe axial_bar" scripts/validation_suite.sh   # some parts
#
# Parts, with their wall time in a full run (one core, the other busy;
# doc/validation.md):
#   fe              mpm-fe on prm/fe_*.prm (FE references)          80 s
#   cantilever      scripts/cantilever_study.sh + plot              1.2 min
#   column          scripts/column_study.sh + plot                  3.7 min
#   thick_cylinder  scripts/thick_cylinder_study.sh + plot          4.5 min
#   convecting_bar  scripts/run_convecting_bar.sh and
#                   scripts/convecting_strip_study.sh               18 s
#   mms             scripts/mms_study.sh 2D and 3D, every family,
#                   + scripts/plot_mms.py                           11 min
#   spinning_disk   scripts/spinning_disk_study.sh with FLIP and the
#                   APIC table at CFL 0.1 (5 runs), the cured panels
#                   and scripts/spinning_disk_sweep.sh over omega
#                   and nu for one turn                             75 min
#   axial_bar       scripts/axial_bar_study.sh                      7 s
#   cooks_membrane  scripts/cooks_membrane_study.sh + plot
#                   (a) 21 runs at h = 4, 2, 1; (b) 14 runs at h = 4
#                   and 2 and 3 at h = 1                           20 min
#   water_column    scripts/water_column_study.sh + plot            1.8 min
#   strip_footing   scripts/strip_footing_study.sh + plot, quasi-static,
#                   standard MPM and CPDI at large deformation, and the
#                   limit loads in small strain on graded grids,
#                   the node average's too
#                   (doc/benchmarks/strip_footing.md)               about 2.5 h
#   ghost_penalty   scripts/ghost_penalty_study.sh, Cook's membrane of
#                   neo-Hookean material at finite strain, every family
#                   and beta (doc/guide/implicit.md)                40 s
#   thick_cylinder_implicit  scripts/thick_cylinder_implicit.sh + plot,
#                   quasi-static (doc/benchmarks/thick_cylinder.md)        35 s
#   implicit_preconditioner  scripts/implicit_scaling.sh for theta-bar
#                   at nu = 0.4999 by AMG and by AMG with cell pressure
#                   (doc/theory/implicit.md), 1 and 2 ranks (QUICK: 1) 90 s
#   column_implicit scripts/column_implicit_study.sh + plot,
#                   quasi-static, every family
#                   (doc/benchmarks/self_weight_column.md)          1 min
#   cantilever_newmark scripts/cantilever_newmark_study.sh + plot,
#                   Newmark with the filter (doc/benchmarks/cantilever.md) 1 min
#   cantilever_aspect scripts/cantilever_aspect_study.sh: L/H 4 to 40,
#                   nu 0 to 0.49, and in 3D L/H 4 to 20
#                   (doc/benchmarks/cantilever.md)        8 + 86 min
#   sliding_block   scripts/sliding_block_study.sh + plots, contact with
#                   friction, the rolling cylinder with and without the
#                   gap check (doc/benchmarks/sliding_block.md)    5.5 min
#   colliding_disks scripts/colliding_disks_study.sh + plot, contact
#                   through an impact (doc/benchmarks/colliding_disks.md) 2 min
#   hertz_contact   scripts/hertz_contact_study.sh + plot, a cylinder
#                   pressed on a plane against Hertz, refined
#                   (doc/benchmarks/hertz_contact.md)              35 min
#   glass_pour      scripts/glass_pour_study.sh + figures, water poured
#                   into a glass, 2D and 3D, standard and both remedies
#                   (doc/benchmarks/glass_pour.md), and
#                   scripts/resting_water_stability.sh from rest, seeded
#                   and sloshing (doc/theory/volumetric_smoothing.md) 9 min
#   recompute       scripts/recompute_measures.py on every run with
#                   particle CSVs and parameters.prm                2.6 min
# Full suite: about 6.5 hours. QUICK=1 (coarse grids, short runs, few
# variants) takes a few
# minutes and writes its results and figures under
# results/validation-quick/ only: it never overwrites doc/figures.
#
# A part that fails is reported in the summary and the suite goes on; the
# exit status is 1 if any part failed.
# Environment: QUICK, PARTS (default: all, in the order above), MPM.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
quick=${QUICK:-0}
parts=${PARTS:-"fe cantilever column thick_cylinder convecting_bar mms spinning_disk axial_bar cooks_membrane water_column strip_footing ghost_penalty thick_cylinder_implicit implicit_preconditioner column_implicit cantilever_newmark cantilever_aspect sliding_block colliding_disks hertz_contact glass_pour recompute"}
export MPM=${MPM:-$root/build/mpm}
fe=$root/build/mpm-fe
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
py=/usr/bin/python3
if [ "$quick" = 1 ]; then
  res=$root/results/validation-quick
  figs=$res/figures
else
  res=$root/results
  figs=$root/doc/figures
fi
sumdir=$root/results/validation
mkdir -p "$res" "$figs" "$sumdir"
summary=$sumdir/summary.txt
[ "$quick" = 1 ] && summary=$sumdir/summary-quick.txt
: > "$summary.tmp"
mkdir -p "$res/logs"
# runs newer than this stamp are this suite's (for the recompute part)
stamp=$res/logs/.suite-started
touch "$stamp"
failed=0

for exe in "$MPM" "$fe"; do
  [ -x "$exe" ] || { echo "$exe missing: run scripts/build.sh first" >&2; exit 1; }
done

# run_part NAME COMMAND...: time a part, keep its screen output in
# $res/logs/NAME.log, record the outcome in the summary.
mkdir -p "$res/logs"
run_part() {
  local name=$1; shift
  local t0=$SECONDS status
  echo "== $name"
  "$@" > "$res/logs/$name.log" 2>&1
  status=$?
  local wall=$(( SECONDS - t0 ))
  if [ $status -eq 0 ]; then
    printf '%-16s %6d s  ok\n' "$name" "$wall" | tee -a "$summary.tmp"
  else
    failed=1
    printf '%-16s %6d s  FAILED (status %d, see %s)\n' "$name" "$wall" "$status" \
      "${res#$root/}/logs/$name.log" | tee -a "$summary.tmp"
    tail -5 "$res/logs/$name.log" | sed 's/^/    /'
  fi
}

part_fe() {
  local dir=$res/fe-reference
  mkdir -p "$dir"
  for f in "$root"/prm/fe_*.prm; do
    local name=$(basename "$f" .prm)
    # the distributed solver's cases run on both cores
    local launch=()
    grep -q "Method = AMG" "$f" && launch=(mpirun -np 2)
    # mpm-fe writes its Output/Directory relative to the working directory
    (cd "$dir" && "${launch[@]}" "$fe" "$f" > "$name.log" 2>&1) || { cat "$dir/$name.log"; return 1; }
    echo "$name: $(grep -iE 'period|displacement|reference' "$dir/$name.log" | tail -2 | tr '\n' ' ')"
  done
}

part_cantilever() {
  if [ "$quick" = 1 ]; then
    # one run of the benchmark file, two periods; its period
    local dir=$res/cantilever
    mkdir -p "$dir"
    cat > "$dir/case.prm" <<PRM
include $root/prm/cantilever_beam.prm
subsection Time stepping
  set End time = 1.4
end
subsection Output
  set Directory = $dir/output
  set Interval = 0.01
  set Write csv = true
end
PRM
    "$MPM" "$dir/case.prm" > "$dir/log.txt" 2>&1 || return 1
    $py "$root/scripts/beam_period.py" "$dir/output"
  else
    "$root/scripts/cantilever_study.sh" "$res/cantilever" &&
      $py "$root/scripts/plot_cantilever.py" "$res/cantilever" "$figs/cantilever_period.png"
  fi
}

part_column() {
  local h=""
  [ "$quick" = 1 ] && h=1
  "$root/scripts/column_study.sh" "$res/column" $h &&
    $py "$root/scripts/plot_column.py" "$res/column" "$figs/self_weight_column.png"
}

part_thick_cylinder() {
  local h=""
  [ "$quick" = 1 ] && h=0.125
  "$root/scripts/thick_cylinder_study.sh" "$res/thick-cylinder" $h &&
    $py "$root/scripts/plot_thick_cylinder.py" "$res/thick-cylinder" "$figs/thick_cylinder.png"
}

part_thick_cylinder_implicit() {
  local h=""
  [ "$quick" = 1 ] && h=0.125
  mkdir -p "$res/thick-cylinder-implicit" &&
    "$root/scripts/thick_cylinder_implicit.sh" $h > "$res/thick-cylinder-implicit/table.md" &&
    $py "$root/scripts/plot_thick_cylinder_implicit.py" "$res/thick-cylinder-implicit/table.md" "$figs/thick_cylinder_implicit.png"
}

part_implicit_preconditioner() {
  local ranks="1 2"
  [ "$quick" = 1 ] && ranks=1
  mkdir -p "$res/implicit-preconditioner" &&
    CASES="cook-b-theta cook-b-split block3d-theta block3d-split" RANKS="$ranks" \
      "$root/scripts/implicit_scaling.sh" > "$res/implicit-preconditioner/table.md"
}

part_cantilever_newmark() {
  "$root/scripts/cantilever_newmark_study.sh" "$res/cantilever-newmark" &&
    $py "$root/scripts/plot_cantilever_newmark.py" "$res/cantilever-newmark/table.txt" "$figs/cantilever_newmark.png"
}

part_cantilever_aspect() {
  if [ "$quick" = 1 ]; then
    JOBS=1 RATIOS=4 NUS=0.3 VARIANTS="standard filter-compliance" \
      "$root/scripts/cantilever_aspect_study.sh" "$res/cantilever-aspect"
  else
    JOBS=1 "$root/scripts/cantilever_aspect_study.sh" "$res/cantilever-aspect" &&
      DIM=3 RATIOS="4 10 20" JOBS=1 \
        "$root/scripts/cantilever_aspect_study.sh" "$res/cantilever-aspect-3d"
  fi
}

part_strip_footing() {
  local study=$root/scripts/strip_footing_study.sh h="" fixed="0.25 0.125 0.0625 0.03125"
  local limit="0.25 0.125 0.0625 0.03125 0.015625"
  # h:edge cell size (the edge's zone does not fit on the coarse grids)
  local edges="0.03125:0.0078125 0.03125:0.00390625 0.03125:0.001953125 0.015625:0.00390625"
  [ "$quick" = 1 ] && h=0.25 fixed=0.25 limit=0.25 edges=
  FAMILIES="standard CPDI" "$study" "$res/strip-footing" $h &&
    GRID=graded GEOMETRY="small strain" END=0.3 SOLVER=direct REMEDIES="standard theta-bar filter" \
      "$study" "$res/strip-footing" $fixed &&
    $py "$root/scripts/plot_strip_footing.py" "$res/strip-footing" "$figs/strip_footing.png" &&
    GRID=graded GEOMETRY="small strain" END=0.3 SOLVER=direct \
      REMEDIES="theta-bar filter standard" "$study" "$res/strip-footing-limit" $limit &&
    $py "$root/scripts/plot_strip_footing_limit.py" "$res/strip-footing-limit" "$figs/strip_footing_limit.png" &&
    GRID=graded GEOMETRY="small strain" END=0.3 SOLVER=direct \
      REMEDIES=node "$study" "$res/strip-footing-node" $limit &&
    for run in $edges; do
      GRID=graded EDGE=${run#*:} GEOMETRY="small strain" END=0.3 SOLVER=direct \
        REMEDIES="theta-bar filter" "$study" "$res/strip-footing-edge" ${run%%:*} || return 1
    done
}

part_ghost_penalty() {
  local families=""
  [ "$quick" = 1 ] && families="standard uGIMP"
  FAMILIES=${families:-"standard uGIMP cpGIMP CPDI CPDI2"} BETAS="0 1e-5 1e-4 1e-3 1e-2" \
    "$root/scripts/ghost_penalty_study.sh" "$res/ghost-penalty"
}

part_sliding_block() {
  if [ "$quick" = 1 ]; then
    CYLINDER_MU=0.3 BLOCK_GAP_MU=0.3 "$root/scripts/sliding_block_study.sh" 0.3 \
      > "$res/sliding-block.txt"
  else
    FIGURE=1 "$root/scripts/sliding_block_study.sh" > "$res/sliding-block.txt"
  fi
}

part_colliding_disks() {
  if [ "$quick" = 1 ]; then
    "$root/scripts/colliding_disks_study.sh" > "$res/colliding-disks.txt"
  else
    FIGURE=1 "$root/scripts/colliding_disks_study.sh" > "$res/colliding-disks.txt"
  fi
}

part_hertz_contact() {
  if [ "$quick" = 1 ]; then
    LEVELS="1 2" PPDS=4 "$root/scripts/hertz_contact_study.sh" \
      "$res/hertz-contact" > "$res/hertz-contact.txt"
  else
    FIGURE=1 "$root/scripts/hertz_contact_study.sh" "$res/hertz-contact" \
      > "$res/hertz-contact.txt"
  fi
}

part_glass_pour() {
  "$root/scripts/resting_water_stability.sh" "$res/resting-water" \
    > "$res/resting-water.txt"
  SLOSH=1e-6 END=6 FLIPS="0.95 0.99 1" CFLS="0.5 0.1" \
    "$root/scripts/resting_water_stability.sh" "$res/resting-water-seeded" \
    > "$res/resting-water-seeded.txt"
  SLOSH=0.1 END=6 FLIPS=0.95 CFLS="0.5 0.1" \
    "$root/scripts/resting_water_stability.sh" "$res/resting-water-slosh" \
    > "$res/resting-water-slosh.txt"
  if [ "$quick" = 1 ]; then
    DIMS=2 "$root/scripts/glass_pour_study.sh" "$res/glass-pour" \
      > "$res/glass-pour.txt"
  else
    FIGURE=1 "$root/scripts/glass_pour_study.sh" "$res/glass-pour" \
      > "$res/glass-pour.txt"
  fi
}

part_column_implicit() {
  local n=""
  [ "$quick" = 1 ] && n="10 20"
  "$root/scripts/column_implicit_study.sh" "$res/column-implicit" $n &&
    $py "$root/scripts/plot_column_implicit.py" "$res/column-implicit" "$figs/column_implicit.png"
}

part_convecting_bar() {
  "$root/scripts/run_convecting_bar.sh" "$res/convecting-bar" &&
    cp "$res/convecting-bar/convecting_bar.png" "$figs/convecting_bar.png" &&
    "$root/scripts/convecting_strip_study.sh" "$res/convecting-strip"
}

part_mms() {
  local families="standard uGIMP cpGIMP CPDI CPDI2"
  if [ "$quick" = 1 ]; then
    NS="8 16" GS=1e-4 "$root/scripts/mms_study.sh" --families "standard CPDI" "$res/mms" &&
      NS="4" GS=1e-4 "$root/scripts/mms_study.sh" --3d --families standard "$res/mms_3d"
  else
    "$root/scripts/mms_study.sh" --families "$families" "$res/mms" &&
      NS="4 8 16" "$root/scripts/mms_study.sh" --3d --families "$families" "$res/mms_3d"
  fi || return 1
  $py "$root/scripts/plot_mms.py" "$figs/manufactured_solution.png" "$res/mms" "$res/mms_3d"
}

part_spinning_disk() {
  if [ "$quick" = 1 ]; then
    END=0.62 CELLS=25 VARIANTS="standard CPDI+filter CPDI+APIC" \
      PLOT="$figs/spinning_disk_variants.png" \
      "$root/scripts/spinning_disk_study.sh" "$res/spinning_disk"
  else
    # FLIP table and figure, then the APIC table at CFL 0.1
    # (doc/benchmarks/spinning_disk.md)
    PLOT="$figs/spinning_disk_variants.png" \
      "$root/scripts/spinning_disk_study.sh" "$res/spinning_disk" &&
      CFL=0.1 VARIANTS="CPDI+APIC CPDI+enriched+APIC CPDI+filter+APIC uGIMP+APIC" \
        PLOT="$res/spinning_disk_apic/variants.png" \
        "$root/scripts/spinning_disk_study.sh" "$res/spinning_disk_apic" &&
      CFL=0.1 VARIANTS="CPDI+filter+force+APIC" PLOT="$res/sd_force_apic/variants.png" \
        "$root/scripts/spinning_disk_study.sh" "$res/sd_force_apic" &&
      END=6.2 INTERVAL=0.155 JOBS=2 PLOT="$figs/spinning_disk_cured.png" \
        VARIANTS="standard+midpoint+leapfrog standard+filter+midpoint+leapfrog
        CPDI+midpoint+leapfrog CPDI+filter+midpoint+leapfrog CPDI+APIC+midpoint+leapfrog
        CPDI+filter+force+APIC+midpoint+leapfrog CPDI+filter+APIC+midpoint+leapfrog
        CPDI+enriched+APIC+midpoint+leapfrog" \
        "$root/scripts/spinning_disk_study.sh" "$res/sd_cured" &&
      "$root/scripts/spinning_disk_sweep.sh" "$res/sd_sweep"
  fi
}

part_axial_bar() {
  "$root/scripts/axial_bar_study.sh" "$res/axial-bar" "$figs/axial_bar.png"
}

part_cooks_membrane() {
  if [ "$quick" = 1 ]; then
    # (b) on the coarsest grid, locked and cured: the plumbing only
    CASES=b VARIANTS="standard theta-bar" \
      "$root/scripts/cooks_membrane_study.sh" "$res/cooks_membrane" 8
  else
    rm -f "$res/cooks_membrane/table.csv"
    CASES=a "$root/scripts/cooks_membrane_study.sh" "$res/cooks_membrane" 4 2 1 &&
      CASES=b "$root/scripts/cooks_membrane_study.sh" "$res/cooks_membrane" 4 2 &&
      CASES=b VARIANTS="theta-bar filter+theta-bar filter-compliance" \
        "$root/scripts/cooks_membrane_study.sh" "$res/cooks_membrane" 1 &&
      $py "$root/scripts/plot_cooks_membrane.py" "$res/cooks_membrane" \
        "$figs/cooks_membrane.png"
  fi
}

part_water_column() {
  PLOT="$figs/water_column.png" \
    "$root/scripts/water_column_study.sh" "$res/water_column"
}

# Every run of this suite that kept particle CSVs: the statistics file's
# benchmark columns recomputed from them.
part_recompute() {
  local n=0 bad=0 dir
  while IFS= read -r stats; do
    dir=$(dirname "$stats")
    [ -f "$dir/parameters.prm" ] || continue
    ls "$dir"/particles-*.csv > /dev/null 2>&1 || continue
    grep -q "^set Benchmark *= *none" "$dir/parameters.prm" && continue
    n=$((n + 1))
    if $py "$root/scripts/recompute_measures.py" "$dir" > "$dir/recompute.txt" 2>&1; then
      echo "ok    ${dir#$root/}: $(tail -2 "$dir/recompute.txt" | head -1)"
    else
      bad=$((bad + 1))
      echo "FAIL  ${dir#$root/}: $(tail -3 "$dir/recompute.txt" | tr '\n' ' ')"
    fi
  done < <(find "$res" -name statistics.txt -newer "$stamp" | sort)
  echo "$n runs checked, $bad disagree"
  [ $n -gt 0 ] && [ $bad -eq 0 ]
}

start=$SECONDS
for p in $parts; do
  if ! declare -F "part_$p" > /dev/null; then
    echo "unknown part '$p'" >&2
    exit 2
  fi
  run_part "$p" "part_$p"
done
total=$(( SECONDS - start ))
{
  echo "validation suite ($([ "$quick" = 1 ] && echo QUICK || echo full)), $(date -u '+%Y-%m-%d %H:%M UTC'), $(git -C "$root" rev-parse --short HEAD 2>/dev/null)"
  echo "results in ${res#$root/}/, figures in ${figs#$root/}/"
  echo
  cat "$summary.tmp"
  printf '%-16s %6d s\n' total "$total"
  if [ -f "$res/logs/recompute.log" ] && [[ " $parts " == *" recompute "* ]]; then
    echo
    echo "recomputed measures (scripts/recompute_measures.py):"
    sed 's/^/  /' "$res/logs/recompute.log"
  fi
} > "$summary"
rm -f "$summary.tmp"
echo "total $total s; summary in ${summary#$root/}"
exit $failed
