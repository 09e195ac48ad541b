#!/usr/bin/env bash
# Long run of a free elastic block: conservation of mass, linear and angular
# momentum, and the energy behaviour, over many steps.
#
# usage: scripts/long_run.sh [STEPS] [VARIANT...]
#   STEPS    number of steps (default 100000)
#   VARIANT  TRANSFER-SCHEME[-FAMILY] with TRANSFER in FLIP, APIC, SCHEME in
#            USF, USL, MUSL and FAMILY a Shape functions/Family (default
#            uGIMP; APIC needs one other than standard). Default variants:
#            FLIP-USL FLIP-MUSL APIC-USL APIC-MUSL FLIP-MUSL-standard
# environment:
#   MPM        the executable (default build/mpm next to this script)
#   WORK       folder for the runs (default a temporary folder, removed)
#   CHECK=1    exit with status 1 unless the mass is unchanged and the
#              linear momentum drift stays below MOMENTUM_TOL (default 1e-10)
#              relative to the momentum scale sqrt(2 M E_kin(0))
#
# The body: a 0.3 x 0.3 neo-Hookean square (8 x 8 cells, 2 x 2 particles
# each: 256 particles) in the middle of a 16 x 16 grid of the unit square,
# no gravity, no boundary contact. Its initial velocity is a slow
# translation, a rigid rotation and a breathing (dilatation) mode, so it
# drifts, spins and vibrates. Fixed step 5e-4 s (0.29 of the stability
# limit): 1e5 steps are 50 s, about four turns.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
steps=${1:-100000}
shift || true
variants=("$@")
[ ${#variants[@]} -eq 0 ] && variants=(FLIP-USL FLIP-MUSL APIC-USL APIC-MUSL
                                        FLIP-MUSL-standard)
tol=${MOMENTUM_TOL:-1e-10}
[ -x "$mpm" ] || { echo "long_run.sh: no executable $mpm (build first)" >&2; exit 1; }

if [ -n "${WORK:-}" ]; then
  work=$WORK
  mkdir -p "$work"
else
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
fi

dt=5e-4
end_time=$(python3 -c "print($steps * $dt)")
interval=$(python3 -c "print($steps * $dt / 200)")

status=0
printf '%-18s %8s %12s %14s %14s %14s %14s\n' variant steps mass_change \
  max_dP_rel max_dL_rel dE_end_rel max_dE_rel
for v in "${variants[@]}"; do
  IFS=- read -r transfer scheme family <<< "$v"
  family=${family:-uGIMP}
  dir=$work/$v
  rm -rf "$dir" && mkdir -p "$dir"
  cat > "$dir/case.prm" <<EOF
set Dimension = 2
subsection Grid
  set Lower corner = 0, 0
  set Upper corner = 1, 1
  set Subdivisions = 16
end
subsection Shape functions
  set Family = $family
end
subsection Time stepping
  set Scheme = $scheme
  set Velocity transfer = $transfer
  set Time step control = fixed
  set Time step = $dt
  set End time = $end_time
  set Maximum number of steps = $steps
end
subsection Output
  set Directory = output
  set Interval = $interval
  set Write vtu = false
  set Write csv = false
  set Progress interval = 1e9
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0.35, 0.35
    set Upper corner = 0.65, 0.65
    set Subdivisions = 8
    set Particles per direction = 2
    set Initial velocity = 1e-3 - 0.5*(y-0.5) + 0.2*(x-0.5); 0.5*(x-0.5) + 0.2*(y-0.5)
    subsection Material
      set Model = neo-Hookean
      set Density = 1000
      subsection Neo-Hookean
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end
    end
  end
end
EOF
  (cd "$dir" && "$mpm" case.prm > screen.txt 2>&1) ||
    { echo "long_run.sh: the run $v failed:" >&2; tail -5 "$dir/screen.txt" >&2; exit 1; }
  python3 - "$dir/output/statistics.txt" "$v" "$tol" > "$dir/figures.txt" <<'EOF' || status=1
import math, sys
path, name, tol = sys.argv[1], sys.argv[2], float(sys.argv[3])
rows = [l.split() for l in open(path)]
head, rows = rows[0], rows[1:]
col = lambda n: [r[head.index(n)] for r in rows]
mass = col("mass")
m0 = float(mass[0])
mass_change = max(abs(float(m) - m0) for m in mass)
mass_exact = all(m == mass[0] for m in mass)  # the printed digits
px, py = [list(map(float, col(c))) for c in ("momentum_x", "momentum_y")]
L = list(map(float, col("angular_momentum_z")))
E = list(map(float, col("total_energy")))
ke0 = float(col("kinetic_energy")[0])
p_scale = math.sqrt(2 * m0 * ke0)
dp = max(math.hypot(a - px[0], b - py[0]) for a, b in zip(px, py)) / p_scale
dl = max(abs(l - L[0]) for l in L) / abs(L[0])
de_end = (E[-1] - E[0]) / E[0]
de_max = max(abs(e - E[0]) for e in E) / E[0]
steps = int(col("step")[-1])
print(f"{name:<18s} {steps:8d} {mass_change:12.3e} {dp:14.3e} {dl:14.3e} "
      f"{de_end:14.3e} {de_max:14.3e}")
sys.exit(0 if mass_exact and dp < tol else 1)
EOF
  cat "$dir/figures.txt"
done
echo "mass_change: max |M(t) - M(0)| [kg]; max_dP_rel: max |P(t) - P(0)| /"
echo "sqrt(2 M E_kin(0)); max_dL_rel: max |L(t) - L(0)| / |L(0)| (about the"
echo "origin); dE_*_rel: (E(t) - E(0)) / E(0), E = kinetic + strain energy."
if [ "${CHECK:-0}" = 1 ] && [ $status != 0 ]; then
  echo "long_run.sh: FAIL: mass changed or momentum drift >= $tol" >&2
  exit 1
fi
exit 0
