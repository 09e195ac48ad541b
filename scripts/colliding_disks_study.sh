#!/usr/bin/env bash
# Colliding disks (prm/colliding_disks.prm, doc/benchmarks/colliding_disks.md):
# one velocity field against each contact law (Coulomb with mu = 0.4), with
# each update scheme, on
# the grid of the parameter file (h = 0.05, CFL 0.4) and, for frictionless
# MUSL, with a smaller step and a finer grid. Prints the kinetic and the
# total energy at t = 3 s over the initial energy, the largest |total
# momentum| over m v0 during the run, and the disks' closing speed at
# t = 3 s over the initial one (negative: separating). A run that stops
# (USL with FLIP, as with one field) is listed with where it stopped. FIGURE=1 writes
# doc/figures/colliding_disks.png (energy against time, MUSL).
# Usage: scripts/colliding_disks_study.sh   (MPM=..., RANKS=n)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| contact law | scheme | h | CFL | kinetic energy | total energy | max momentum | closing speed |"
echo "|---|---|---|---|---|---|---|---|"
run() { # law scheme subdivisions cfl
  local tag="${1// /_}_$2_$3_$4"
  cat > "$work/case.prm" <<PRM
include $root/prm/colliding_disks.prm
subsection Grid
  set Subdivisions = $3
end
subsection Time stepping
  set Scheme = $2
  set CFL number = $4
end
subsection Contact
  set Contact law = $1
  set Friction coefficient = $([ "$1" = Coulomb ] && echo 0.4 || echo 0)
end
subsection Output
  set Directory = $work/out
  set Write vtu = false
  set Write csv = true
end
PRM
  rm -rf "$work/out"
  if ! mpirun -np $ranks "$mpm" "$work/case.prm" > "$work/log" 2>&1; then
    echo "| $1 | $2 | $(python3 -c "print(1 / $3)") | $4 | $(grep -o 'stopped at step [0-9]* (t = [0-9.]*)' "$work/log" | head -1) ||||"
    return
  fi
  cp "$work/out/statistics.txt" "$work/stats_$tag.txt"
  /usr/bin/python3 - "$work/out" "$1" "$2" "$3" "$4" <<'PY'
import glob, math, sys
import pandas as pd
out, law, scheme, n, cfl = sys.argv[1:]
s = pd.read_csv(f"{out}/statistics.txt", sep=r"\s+")
e0 = s.total_energy.iloc[0]
m_v0 = 0.5 * s.mass.iloc[0] * 0.1 * math.sqrt(2)
p = (s.momentum_x ** 2 + s.momentum_y ** 2) ** 0.5 / m_v0
last = sorted(glob.glob(f"{out}/particles-*.csv"))[-1]
q = pd.read_csv(last)
v = q.groupby("body").apply(
    lambda g: ((g.mass * g.v_x).sum() / g.mass.sum(),
               (g.mass * g.v_y).sum() / g.mass.sum()))
closing = -((v[1][0] - v[0][0]) + (v[1][1] - v[0][1])) / math.sqrt(2)
print(f"| {law} | {scheme} | {1 / int(n):g} | {cfl} | "
      f"{s.kinetic_energy.iloc[-1] / e0:.3f} | {s.total_energy.iloc[-1] / e0:.3f} | "
      f"{p.max():.1e} | {closing / (0.2 * math.sqrt(2)):+.2f} |")
PY
}
for law in none "no separation" frictionless Coulomb; do
  for scheme in MUSL USF USL; do
    run "$law" $scheme 20 0.4
  done
done
run frictionless MUSL 20 0.1
run frictionless MUSL 40 0.4
if [ "${FIGURE:-0}" = 1 ]; then
  /usr/bin/python3 "$root/scripts/plot_colliding_disks.py" "$work" \
    "$root/doc/figures/colliding_disks.png"
fi
