#!/usr/bin/env bash
# One command from a fresh Debian 12 machine: install, build, and run the
# first example, the spinning disk of the seed's closing figures: a disk
# turning in its steady state, after almost one turn (t = 6.2 s), computed
# five ways side by side:
#   standard MPM, standard MPM + assumed-stress filter, CPDI, CPDI + filter,
#   and CPDI + filter (Filtered stress = force only) + APIC.
# sigma_rr should stay the exact parabola and sigma_rt zero. The first four
# are the seed's panels (noisy; the filter helps but does not cure); the
# fifth stays within 2% of the exact field.
#
# Set-up: coarser than the benchmark so that the five runs take about two
# minutes on two cores. prm/spinning_disk.prm with h = 0.1
# (25 x 25 cells) instead of 0.05, 3 072 particles instead of 12 288 (the
# same, about 3 particles per cell and direction) and CFL 0.1 for every variant
# (APIC needs the small step, see the spinning disk page of the manual).
# The benchmark's set-up and its tables: scripts/spinning_disk_study.sh.
# Two variants run at a time, one per core.
#
# Environment: FIGURE (where the picture goes, default
# results/first_run/first_run.png; the manual's picture is made with
# FIGURE=doc/figures/first_run.png), CELLS, REFINEMENTS, CFL, JOBS (as in
# scripts/spinning_disk_study.sh; defaults 25, 3, 0.1, 2).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh" mpm

out=$root/results/first_run
figure=${FIGURE:-$out/first_run.png}
cells=${CELLS:-25}
refinements=${REFINEMENTS:-3}
cfl=${CFL:-0.1}
jobs=${JOBS:-2}
# picture order; the runs start with the slowest so the two cores finish together
variants="standard standard+filter CPDI CPDI+filter CPDI+filter+force+APIC"
run_order="CPDI+filter+force+APIC CPDI+filter CPDI standard+filter standard"
h=$(awk -v n="$cells" 'BEGIN{print 2.5/n}')
particles=$(( 12 * 4 ** refinements * 4 ))
setup="h = $h, $particles particles, CFL $cfl"
echo "Spinning disk to t = 6.2 s, five variants, $jobs at a time ($setup;"
echo "the benchmark is h = 0.05, 12288 particles: scripts/spinning_disk_study.sh)"
mkdir -p "$out"
CELLS=$cells REFINEMENTS=$refinements CFL=$cfl JOBS=$jobs VTU=true INTERVAL=0.62 \
  VARIANTS="$run_order" PLOT=none "$root/scripts/spinning_disk_study.sh" "$out"
echo
mkdir -p "$(dirname "$figure")"
/usr/bin/python3 "$root/scripts/plot_spinning_disk_variants.py" "$out" "$figure" \
  $variants --target --table \
  --title "Spinning disk at t = 6.2 s (almost one turn): $setup"
echo
echo "Results:  $out/<variant>/output/ (open particles.pvd in ParaView;"
echo "          statistics.txt has energies, momenta and the sigma_rr / sigma_rt errors)"
echo "Table:    $out/errors.csv"
echo "Picture:  $figure"
