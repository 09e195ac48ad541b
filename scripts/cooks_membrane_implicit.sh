#!/usr/bin/env bash
# Cook's membrane (prm/cooks_membrane.prm, plane stress, standard MPM) by
# the quasi-static integrator in one load step, on grids h = 4, 2, 1, 0.5,
# 0.25: the tip displacement ratios to the FE reference, Newton and linear
# (AMG-preconditioned GMRES) iterations, and the wall time of the run.
# CASE=b takes the nearly incompressible panel in plane strain instead
# (prm/cooks_membrane_plane_strain.prm, nu = 0.4999).
# FAMILY=uGIMP|cpGIMP|CPDI|CPDI2 runs that shape-function family instead
# of standard MPM; FILTER=mass|compliance adds the assumed-stress filter
# with that metric; SMOOTHING=cell adds theta-bar; SUPPORT=x sets
# Implicit solver/Minimum nodal support.
# (The case file: scripts/cooks_membrane_implicit_case.sh.)
# Usage: [CASE=b] [RANKS=n] [FAMILY=...] [FILTER=...] [SMOOTHING=cell] [SUPPORT=x]
#        scripts/cooks_membrane_implicit.sh [h values...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| h | grid unknowns | corner ratio | mid ratio | Newton | linear per solve | wall [s] |"
echo "|---|---|---|---|---|---|---|"
for h in ${@:-4 2 1 0.5 0.25}; do
  read -r nx ny <<< "$(python3 -c "print(round(52/$h), round(68/$h))")"
  "$root/scripts/cooks_membrane_implicit_case.sh" "$h" "$work/out" > "$work/case.prm"
  start=$(date +%s.%N)
  (cd "$work" && mpirun -np "$ranks" "$mpm" case.prm > log)
  end=$(date +%s.%N)
  python3 - "$work/out/statistics.txt" "$h" "$nx" "$ny" "$start" "$end" <<'PY'
import sys
rows = [l.split() for l in open(sys.argv[1])]
head, last = rows[0], rows[-1]
v = dict(zip(head, last))
h, nx, ny = sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
newton = int(float(v["newton_iterations"]))
linear = int(float(v["linear_iterations"]))
print("| %s | %d | %.4f | %.4f | %d | %.1f | %.2f |" % (
    h, 2 * (nx + 1) * (ny + 1), float(v["corner_ratio"]), float(v["mid_ratio"]),
    newton, linear / max(newton, 1), float(sys.argv[6]) - float(sys.argv[5])))
PY
done
