#!/usr/bin/env bash
# Water at rest under gravity (doc/theory/volumetric_smoothing.md,
# "Limits"; doc/benchmarks/glass_pour.md): a layer 0.06 m deep across a
# 0.2 m box with slip walls (h = 0.01, 2 x 2 particles per cell), starting
# in hydrostatic equilibrium, for 3 s. Standard MPM stays at rest; with
# Volumetric smoothing = cell or node a disturbance grows from round-off.
# Prints, per variant and CFL number, the growth rate of |momentum_x|
# (fitted where it lies between 1e-11 and 1e-5), the largest speed at the
# end, the particles' top over the level their volume gives (1 when
# the water fills its volume; below 1 when its particles crowd), and the
# particles' volume in the bottom and the top cell row over the row's
# area (1 when the particles tile the rows). With SLOSH=v the layer
# starts with the velocity v_x = v sin(pi x / 0.2) y / 0.06 instead of
# at rest, and sloshes until the viscosity and the FLIP blend stop it.
# Usage: scripts/resting_water_stability.sh [RESULTS]
#        (MPM=..., VARIANTS="none cell node", FLIPS="0.95 1",
#         CFLS="0.5 0.25 0.1", END=3, SLOSH=0; about 1 minute)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
results=${1:-$root/results/resting_water}
mkdir -p "$results"
echo "| smoothing | FLIP fraction | CFL | growth rate of momentum_x [1/s] | max speed at the end [m/s] | top / volume level | bottom row fill | top row fill |"
echo "|---|---|---|---|---|---|---|---|"
for variant in ${VARIANTS:-none cell node}; do
 for flip in ${FLIPS:-0.95 1}; do
  for cfl in ${CFLS:-0.5 0.25 0.1}; do
    name="${variant}_flip${flip}_cfl${cfl}"
    cat > "$results/$name.prm" <<PRM
set Dimension = 2
set Constants = g=9.81, rho=1000, depth=0.06
subsection Grid
  set Upper corner = 0.2, 0.2
  set Subdivisions = 20
end
subsection Time stepping
  set End time = ${END:-3}
  set CFL number = $cfl
  set FLIP fraction = $flip
end
subsection Boundary conditions
  set Slip boundary ids = 0, 1, 2, 3
end
subsection Output
  set Directory = $results/$name
  set Interval = 0.1
  set Write vtu = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0, 0
    set Upper corner = 0.2, 0.06
    set Subdivisions = 20, 6
    set Body force = 0; -g
    set Initial velocity = ${SLOSH:-0}*sin(pi*x/0.2)*y/depth; 0
    set Initial stress = -rho*g*(depth-y); -rho*g*(depth-y); 0; -rho*g*(depth-y)
    subsection Locking remedies
      set Volumetric smoothing = $variant
    end
    subsection Material
      set Model = Newtonian fluid
      set Density = rho
      subsection Newtonian fluid
        set Viscosity = 1e-3
        set Equation of state = Tait
        set Bulk modulus = 2.5e5
        set Tait exponent = 7
      end
    end
  end
end
PRM
    "$mpm" "$results/$name.prm" > "$results/$name.log"
    /usr/bin/python3 - "$results/$name" "$variant" "$flip" "$cfl" <<'PY'
import glob, sys
import numpy as np
run, variant, flip, cfl = sys.argv[1:]
with open(run + "/statistics.txt") as f:
    names = f.readline().split()
rows = np.loadtxt(run + "/statistics.txt", skiprows=1)
t = rows[:, names.index("time")]
m = np.abs(rows[:, names.index("momentum_x")])
fit = (m > 1e-11) & (m < 1e-5)
rate = f"{np.polyfit(t[fit], np.log(m[fit]), 1)[0]:.1f}" if fit.sum() >= 3 else "none"
d = np.genfromtxt(sorted(glob.glob(run + "/particles-*.csv"))[-1],
                  delimiter=",", names=True)
speed = np.sqrt(d["v_x"] ** 2 + d["v_y"] ** 2).max()
top = np.percentile(d["y"] + np.sqrt(d["volume"]) / 2, 99)
row = np.floor(d["y"] / 0.01)
fill = [d["volume"][row == r].sum() / (0.2 * 0.01) for r in (0, 5)]
print(f"| {variant} | {flip} | {cfl} | {rate} | {speed:.2g} | {top / (d['volume'].sum() / 0.2):.2f} | {fill[0]:.3f} | {fill[1]:.3f} |")
PY
  done
 done
done
