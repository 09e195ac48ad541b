#!/usr/bin/env bash
# How the implicit step scales with the grid: for each case and number of
# ranks, the unknowns (dim x grid nodes), Newton iterations, AMG-Krylov
# iterations per linear solve and wall time per load step (the step's
# phases from mpm's timer table: set-up, assembly, solve, stress update,
# G2P, position update; without the run's set-up and output).
# Cases:
#   cook-a  Cook's membrane, plane stress (prm/cooks_membrane.prm), one
#           load step, h = 2, 1, 0.5, 0.25, 0.125 (AMG-GMRES)
#   cook-b  the same nearly incompressible in plane strain
#           (prm/cooks_membrane_plane_strain.prm, nu = 0.4999), h = 2, 1,
#           0.5
#   cook-b-theta  cook-b with Volumetric smoothing = cell (theta-bar),
#           h = 2, 1, 0.5, preconditioned by AMG (at h = 0.25 its GMRES
#           does not converge in 2000 iterations)
#   cook-b-split  the same with Preconditioner = AMG with cell pressure,
#           h = 2, 1, 0.5, 0.25
#   block3d a unit cube of linear elastic material (nu = 0.3) on a fixed
#           base under its own weight, 4 to 32 cells per direction with
#           2^3 particles per cell, one load step (AMG-GMRES)
#   block3d-theta, block3d-split  the cube at nu = 0.4999 with theta-bar,
#           4 to 16 cells per direction, by AMG and by AMG with cell
#           pressure
# GAMMA sets Implicit solver/Cell pressure gamma of the split cases.
# SOLVER sets Implicit solver/Linear solver (default GMRES: the AMG
# figures, which automatic would replace by direct solves at most of these
# sizes) and DIRECT its Direct solver (MUMPS or KLU); the "linear per
# solve" column is 1 for a direct solve.
# Usage: [CASES="cook-a cook-b block3d"] [RANKS="1 2"] scripts/implicit_scaling.sh
# (the default cases; the others by name)
# About 5 minutes for everything on 2 cores. Run it on an otherwise idle
# machine.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
cases=${CASES:-cook-a cook-b block3d}
ranks_list=${RANKS:-1 2}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

block3d() { # cells per direction [Poisson's ratio, smoothing, preconditioner]
  cat <<PRM
set Dimension = 3
subsection Grid
  set Lower corner = 0, 0, 0
  set Upper corner = 1, 1, 1
  set Subdivisions = $1
end
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = 1
  set End time = 1
end
subsection Boundary conditions
  # the base z = 0 fixed
  set Fixed boundary ids = 4
end
subsection Output
  set Directory = $work/out
  set Interval = 1
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0, 0, 0
    set Upper corner = 1, 1, 1
    set Subdivisions = $1
    set Particles per direction = 2
    set Body force = 0; 0; -10*t
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = ${2:-0.3}
      end
    end
    subsection Locking remedies
      set Volumetric smoothing = ${3:-none}
    end
  end
end
subsection Implicit solver
  set Preconditioner = ${4:-AMG}
  set Cell pressure gamma = ${GAMMA:-10}
end
PRM
}

echo "| case | ranks | grid | unknowns | particles | Newton | linear per solve | time per step [s] |"
echo "|---|---|---|---|---|---|---|---|"
for c in $cases; do
  case $c in
    cook-a) sizes="2 1 0.5 0.25 0.125" ;;
    cook-b) sizes="2 1 0.5" ;;
    cook-b-theta) sizes="2 1 0.5" ;;
    cook-b-split) sizes="2 1 0.5 0.25" ;;
    block3d) sizes="4 8 16 32" ;;
    block3d-theta|block3d-split) sizes="4 8 16" ;;
    *) echo "unknown case $c" >&2; exit 1 ;;
  esac
  for ranks in $ranks_list; do
    for s in $sizes; do
      case $c in
        cook-a) "$root/scripts/cooks_membrane_implicit_case.sh" "$s" "$work/out" ;;
        cook-b) CASE=b "$root/scripts/cooks_membrane_implicit_case.sh" "$s" "$work/out" ;;
        cook-b-theta) CASE=b SMOOTHING=cell "$root/scripts/cooks_membrane_implicit_case.sh" "$s" "$work/out" ;;
        cook-b-split) CASE=b SMOOTHING=cell PRECONDITIONER="AMG with cell pressure" \
          "$root/scripts/cooks_membrane_implicit_case.sh" "$s" "$work/out" ;;
        block3d) block3d "$s" ;;
        block3d-theta) block3d "$s" 0.4999 cell ;;
        block3d-split) block3d "$s" 0.4999 cell "AMG with cell pressure" ;;
      esac > "$work/case.prm"
      printf 'subsection Implicit solver\n  set Linear solver = %s\n  set Direct solver = %s\nend\n' \
        "${SOLVER:-GMRES}" "${DIRECT:-MUMPS}" >> "$work/case.prm"
      rm -rf "$work/out"
      (cd "$work" && mpirun -np "$ranks" "$mpm" case.prm > log) \
        || { tail -5 "$work/log"; exit 1; }
      python3 - "$work/log" "$work/out/statistics.txt" "$c" "$ranks" "$s" <<'PY'
import re
import sys
log, stats, case, ranks, size = sys.argv[1:]
text = open(log).read()
nodes = int(re.search(r"grid: \d+ cells, (\d+) nodes", text).group(1))
particles = int(re.search(r"particles: (\d+)", text).group(1))
dim = 3 if case.startswith("block3d") else 2
phases = ("implicit set-up", "implicit assembly", "implicit linear solve",
          "stress update", "G2P", "position update", "stress filter")
wall = sum(float(m.group(1)) for m in
           re.finditer(r"\| (?:%s) +\| +\d+ \| +([0-9.e+-]+)s" %
                       "|".join(phases), text))
rows = [l.split() for l in open(stats)]
v = dict(zip(rows[0], rows[-1]))
steps = int(float(v["step"]))
newton = int(float(v["newton_iterations"]))
linear = int(float(v["linear_iterations"]))
grid = f"h = {size}" if dim == 2 else f"{size}^3"
print("| %s | %s | %s | %d | %d | %d | %.1f | %.2f |" % (
    case, ranks, grid, dim * nodes, particles, newton,
    linear / max(newton, 1), wall / max(steps, 1)))
PY
    done
  done
done
