#!/usr/bin/env bash
# Instructions per particle-update of the time step, counted by callgrind
# (repeatable whatever else the machine does, unlike wall time), for one or
# more builds side by side: the throughput case (prm/throughput_2d.prm or
# _3d) with a small block, 20 steps, collection only inside
# Simulator<dim>::do_time_step.
# Usage: scripts/instructions_per_update.sh [mpm binaries...]
#   (default build/mpm); DIM=2|3, CELLS (default 64 in 2D, 16 in 3D),
#   VARIANTS (default: standard filter uGIMP cpGIMP CPDI CPDI2).
# Needs valgrind (apt-get install valgrind). Each build runs in parallel.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
dim=${DIM:-2}
cells=${CELLS:-$([ "$dim" = 3 ] && echo 16 || echo 64)}
binaries=("$@")
[ ${#binaries[@]} -gt 0 ] || binaries=("$root/build/mpm")
for i in "${!binaries[@]}"; do # the runs start in their own directories
  binaries[$i]=$(realpath "${binaries[$i]}")
done
work=$(mktemp -d)
for v in ${VARIANTS:-standard filter uGIMP cpGIMP CPDI CPDI2}; do
  line="${dim}D $v:"
  for i in "${!binaries[@]}"; do
    w="$work/$v-$i"
    mkdir -p "$w"
    {
      "$root/scripts/throughput_case.sh" "$dim" "$cells" "$v"
      printf 'subsection Time stepping\n  set Maximum number of steps = 20\nend\n'
    } > "$w/case.prm"
    (cd "$w" && valgrind --tool=callgrind --callgrind-out-file=cg.out \
      --collect-atstart=no "--toggle-collect=mpm::Simulator<$dim>::do_time_step(double)" \
      "${binaries[$i]}" case.prm > log 2> err) &
  done
  wait
  for i in "${!binaries[@]}"; do
    w="$work/$v-$i"
    n=$(sed -n 's/^  particles: //p' "$w/log")
    ir=$(sed -n 's/.*Collected : \([0-9]*\).*/\1/p' "$w/err")
    line="$line $(python3 -c "print('%.1f' % ($ir / ($n * 20)))")"
  done
  echo "$line"
done
rm -rf "$work"
