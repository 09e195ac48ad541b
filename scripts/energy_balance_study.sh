#!/usr/bin/env bash
# The energy balance of two colliding elastic disks (doc/theory/statistics_and_conservation.md,
# "Energy balance"): growth of kinetic + strain energy over its initial
# value, largest and final, for USL, MUSL and USF, linear elastic at
# velocity components +-0.1 and +-0.5 (c = 1), and neo-Hookean at +-0.5.
# Usage: scripts/energy_balance_study.sh   (about 2 minutes)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
base=$root/tests/output/colliding_disks_fast.prm

run() { # LABEL SCHEME SPEED STEP END MODEL
  local label=$1 scheme=$2 v=$3 dt=$4 end=$5 model=$6 section
  section=$([ "$model" = neo-Hookean ] && echo Neo-Hookean || echo "Linear elastic")
  sed "s/set Scheme = USL/set Scheme = $scheme/
       s/Time step = 0.0002/Time step = $dt/
       s/End time = 0.9/End time = $end/
       s/= 0.5; 0.5/= $v; $v/
       s/= -0.5; -0.5/= -$v; -$v/
       s/Model = linear elastic/Model = $model/
       s/subsection Linear elastic/subsection $section/
       s/set Energy balance check = .*//" "$base" > case.prm
  rm -rf results
  "$mpm" case.prm > log.txt 2>&1 || true # the fast disks reach the walls
  /usr/bin/python3 - "$label" <<'P'
import sys, pandas as pd
d = pd.read_csv("results/statistics.txt", sep=r"\s+")
e = d.kinetic_energy + d.strain_energy
print(f"{sys.argv[1]:40s} largest {100*(e.max()/e[0]-1):6.1f} %   "
      f"final {100*(e.iloc[-1]/e[0]-1):6.1f} %   (to t = {d.time.iloc[-1]:.2f})")
P
}
for scheme in USL MUSL USF; do
  run "+-0.1, linear elastic, $scheme" $scheme 0.1 0.001 4 "linear elastic"
done
for scheme in USL MUSL USF; do
  run "+-0.5, linear elastic, $scheme" $scheme 0.5 0.0002 1.3 "linear elastic"
done
for scheme in USL MUSL; do
  run "+-0.5, neo-Hookean, $scheme" $scheme 0.5 0.0002 1.3 neo-Hookean
done
