#!/usr/bin/env bash
# Does a run repeat itself bit for bit? Runs CASE.prm N times on NP ranks,
# each in a fresh folder, and counts the distinct results: the statistics
# file and the last checkpoint's particles (if the case writes
# checkpoints), hashed together. Prints one line per distinct result (how
# many runs gave it) and "distinct: K"; K = 1 when every run is equal bit
# for bit.
# Usage: scripts/repeatability.sh CASE.prm NP N [OUT]
#   e.g. scripts/repeatability.sh tests/checkpoint/moving_boundary_2d.prm 2 30
#   (about 1.5 s a run)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
case=$(realpath "$1") np=$2 n=$3
out=$(realpath -m "${4:-$root/results/repeatability}")
mpm=${MPM:-$root/build/mpm}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
mkdir -p "$out"
for i in $(seq 1 "$n"); do
  rm -rf "$out/run"; mkdir -p "$out/run"
  (cd "$out/run" && mpirun -np "$np" "$mpm" "$case" > screen.txt 2>&1) \
    || { cat "$out/run/screen.txt" >&2; echo "run $i failed" >&2; exit 1; }
  # the case's output folder, wherever its Output/Directory puts it
  stats=$(find "$out/run" -name statistics.txt -not -path '*/checkpoint/*' | head -1)
  [ -n "$stats" ] || { echo "run $i wrote no statistics.txt" >&2; exit 1; }
  results=$(dirname "$stats")
  last=$(cat "$results/checkpoint/latest.txt" 2>/dev/null || true)
  cat "$stats" ${last:+"$results/checkpoint/$last/particle_handler.txt"} | md5sum
done | sort | uniq -c | tee "$out/hashes.txt"
echo "distinct: $(wc -l < "$out/hashes.txt")"
