#!/usr/bin/env bash
# How the quasi-static result depends on the load step: the laterally
# confined column (neo-Hookean, nu = 0.3, E = 1 MPa, rho = 80, g = 10,
# H = 10, h = 0.5) under its full weight in N = 1, 4, 20 quasi-static load
# steps, and by the explicit integrator ramped over 1 s and damped to rest
# at t = 3. Prints the strain energy of each (the particles' F composes the
# step's incremental maps, whose shape functions are those of the
# particles' positions at the start of each step).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
case_file() { # integrator-specific Time stepping entries
  cat <<PRM
set Dimension = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 11
  set Subdivisions = 2, 22
end
subsection Time stepping
$1
end
subsection Boundary conditions
  set Slip boundary ids = 0, 1, 2
end
subsection Output
  set Directory = out
  set Interval = 0
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Upper corner = 1, 10
    set Lower corner = 0, 0
    set Subdivisions = 2, 20
    set Body force = 0; -10*min(t, 1)
    subsection Material
      set Model = neo-Hookean
      set Density = 80
      subsection Neo-Hookean
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end
    end
  end
end
PRM
}
energy() { python3 -c "
r = [l.split() for l in open('$work/out/statistics.txt')]
print(dict(zip(r[0], r[-1]))['strain_energy'])"; }
echo "| run | steps | strain energy [J] |"
echo "|---|---|---|"
for n in 1 4 20; do
  case_file "  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = $(python3 -c "print(1 / $n)")
  set End time = 1" > "$work/case.prm"
  (cd "$work" && rm -rf out && "$mpm" case.prm > log)
  echo "| quasi-static | $n | $(energy) |"
done
case_file "  set End time = 3
  set Damping coefficient = 20" > "$work/case.prm"
(cd "$work" && rm -rf out && "$mpm" case.prm > log)
echo "| explicit, damped | $(sed -n 's/.*step *\([0-9]*\)  t = .*/\1/p' "$work/log" | tail -1) | $(energy) |"
