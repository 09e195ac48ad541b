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
# Usage: [CASE=b] [RANKS=n] [FAMILY=...] [FILTER=...] [SMOOTHING=cell] [SUPPORT=x]
#        scripts/cooks_membrane_implicit.sh [h values...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
family=${FAMILY:-standard}
smoothing=${SMOOTHING:-none}
case_prm=cooks_membrane.prm load="F=1e-3, uy_ref=25.19, uy_ref_mid=23.967" moduli="E=1"
if [ "${CASE:-a}" = b ]; then
  case_prm=cooks_membrane_plane_strain.prm
  load="F=1, uy_ref=0.07771, uy_ref_mid=0.07404" moduli="E=250"
fi
filter=none metric=mass
[ -n "${FILTER:-}" ] && filter="assumed stress" metric=$FILTER
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| h | grid unknowns | corner ratio | mid ratio | Newton | linear per solve | wall [s] |"
echo "|---|---|---|---|---|---|---|"
for h in ${@:-4 2 1 0.5 0.25}; do
  read -r nx ny nb <<< "$(python3 -c "print(round(52/$h), round(68/$h), round(48/$h))")"
  cat > "$work/case.prm" <<PRM
include $root/prm/$case_prm
set Constants = $load, r_fit=$h, tr=250, $moduli, rho=1
subsection Grid
  set Subdivisions = $nx, $ny
end
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 250
  set End time = 250
  set Damping coefficient = 0
end
subsection Shape functions
  set Family = $family
end
subsection Implicit solver
  set Minimum nodal support = ${SUPPORT:-1e-4}
end
subsection Output
  set Directory = $work/out
  set Interval = 250
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $nb
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = $metric
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
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
