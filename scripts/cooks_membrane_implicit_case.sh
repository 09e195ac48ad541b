#!/usr/bin/env bash
# The parameter file of Cook's membrane in one quasi-static load step at
# grid size H, its output in OUTDIR, written to standard output (for
# scripts/cooks_membrane_implicit.sh and scripts/implicit_scaling.sh).
# CASE=b: the nearly incompressible panel in plane strain
# (prm/cooks_membrane_plane_strain.prm, nu = 0.4999) instead of plane
# stress; FAMILY=uGIMP|cpGIMP|CPDI|CPDI2 the shape-function family;
# FILTER=mass|compliance the assumed-stress filter with that metric;
# SMOOTHING=cell theta-bar; SUPPORT=x Implicit solver/Minimum nodal
# support; PRECONDITIONER="AMG with cell pressure" Implicit
# solver/Preconditioner, GAMMA its Cell pressure gamma; GHOST=beta
# Implicit solver/Ghost penalty; SOLVER Implicit solver/Linear solver
# (default GMRES: the AMG figures of the pages, which automatic would
# replace by direct solves at these sizes) and DIRECT its Direct solver.
# Usage: scripts/cooks_membrane_implicit_case.sh H OUTDIR > case.prm
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
h=$1 out=$2
case_prm=cooks_membrane.prm load="F=1e-3, uy_ref=25.19, uy_ref_mid=23.967" moduli="E=1"
if [ "${CASE:-a}" = b ]; then
  case_prm=cooks_membrane_plane_strain.prm
  load="F=1, uy_ref=0.07771, uy_ref_mid=0.07404" moduli="E=250"
fi
filter=none metric=mass
[ -n "${FILTER:-}" ] && filter="assumed stress" metric=$FILTER
read -r nx ny nb <<< "$(python3 -c "print(round(52/$h), round(68/$h), round(48/$h))")"
cat <<PRM
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
  set Family = ${FAMILY:-standard}
end
subsection Implicit solver
  set Linear solver = ${SOLVER:-GMRES}
  set Direct solver = ${DIRECT:-MUMPS}
  set Minimum nodal support = ${SUPPORT:-1e-4}
  set Preconditioner = ${PRECONDITIONER:-AMG}
  set Cell pressure gamma = ${GAMMA:-10}
  set Ghost penalty = ${GHOST:-0}
end
subsection Output
  set Directory = $out
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
      set Volumetric smoothing = ${SMOOTHING:-none}
    end
  end
end
PRM
