#!/usr/bin/env bash
# Thick-walled cylinder under internal pressure by the quasi-static
# integrator (prm/thick_cylinder_quasi_static.prm, one load step): standard
# MPM, Volumetric smoothing = cell (theta-bar for the linear elastic
# model) and Volumetric smoothing = node (the node average) for nu = 0.3, 0.49, 0.499, 0.4999 on background grids h = 0.125,
# 0.0625, 0.03125 (body mesh of the same size, 3x3 particles per body
# cell). Prints the benchmark's columns (u_r(inner)/exact, pressure and
# sigma_rr errors and checkerboard, divided by p), Newton and linear
# iterations and the wall time of each run. VARIANTS="standard theta-bar
# node theta-bar-split" adds theta-bar preconditioned by Implicit
# solver/Preconditioner = AMG with cell pressure (the same displacements,
# fewer GMRES iterations). SOLVER sets Implicit solver/Linear solver
# (default GMRES: the iteration counts of the page; automatic would solve
# these sizes directly).
# Usage: scripts/thick_cylinder_implicit.sh [h values...]   (RANKS=n, MPM=..., VARIANTS=...)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-1}
nus=${NUS:-0.3 0.49 0.499 0.4999}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| nu | h | variant | u_r ratio | pressure error | sigma_rr error | checkerboard | Newton | linear | wall [s] |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for h in ${@:-0.125 0.0625 0.03125}; do
  nx=$(python3 -c "print(round(2.5/$h))")
  nr=$(python3 -c "print(round(1/$h))")
  nt=$(python3 -c "import math; print(round(math.pi/4*3/$h))")
  mesh="$work/quarter_annulus_${nr}x${nt}.ucd"
  "$root/scripts/make_quarter_annulus.py" "$mesh" 1 2 $nr $nt
  for nu in $nus; do
    for variant in ${VARIANTS:-standard theta-bar node}; do
      smoothing=none preconditioner=AMG
      [ $variant != standard ] && smoothing=cell
      [ $variant = node ] && smoothing=node
      [ $variant = theta-bar-split ] && preconditioner="AMG with cell pressure"
      cat > "$work/case.prm" <<PRM
include $root/prm/thick_cylinder_quasi_static.prm
set Constants = a=1, b=2, p=1e3, E=1e6, nu=$nu, rho=1000, tr=0.2
subsection Grid
  set Subdivisions = $nx
end
subsection Output
  set Directory = $work/out
  set Write vtu = false
  set Write csv = false
end
subsection Implicit solver
  set Linear solver = ${SOLVER:-GMRES}
  set Preconditioner = $preconditioner
end
subsection Bodies
  subsection Body 0
    set Mesh file = $mesh
    subsection Locking remedies
      set Volumetric smoothing = $smoothing
    end
  end
end
PRM
      rm -rf "$work/out"
      start=$(date +%s.%N)
      mpirun -np $ranks "$mpm" "$work/case.prm" > "$work/log"
      wall=$(python3 -c "import time; print(f'{time.time() - $start:.2f}')")
      python3 - "$work/out/statistics.txt" "$nu" "$h" "$variant" "$wall" <<'PY'
import sys
path, nu, h, variant, wall = sys.argv[1:]
lines = [l.split() for l in open(path) if l.strip()]
names, last = lines[0], lines[-1]
col = lambda n: last[names.index(n)]
b = [float(col(n)) for n in
     ("ur_inner_ratio", "pressure_error", "sigma_rr_error", "checkerboard")]
print(f"| {nu} | {h} | {variant} | {b[0]:.4f} | {b[1]:.4f} | {b[2]:.4f} | "
      f"{b[3]:.4f} | {col('newton_iterations')} | {col('linear_iterations')} | {wall} |")
PY
    done
  done
done
