#!/usr/bin/env bash
# The ghost penalty (Implicit solver/Ghost penalty) on Cook's membrane of
# neo-Hookean material in plane strain at finite strain
# (prm/cooks_membrane.prm, quasi-static, the shear load F ramped over t = 1
# in steps of 0.1, nu = 0.3, E = 1). For each family of FAMILIES (default
# "standard uGIMP cpGIMP CPDI") and beta of BETAS (default "0 1e-4 1e-3
# 1e-2"), prints u_y(48, 52) after four steps (F = 0.04 at LOAD=0.1) and
# at the end (t = 1), or where the run stopped, the Newton iterations and
# the step cuts. LOAD (default 0.1) is F; STEP (default 0.1) the step.
# Usage: scripts/ghost_penalty_study.sh [OUT]   (MPM=...)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
out=$(realpath -m "${1:-results/ghost_penalty}")
mkdir -p "$out"
echo "| family | beta | u_y(48,52) at t = 0.4 | at the end | t reached | Newton | step cuts | wall [s] |"
echo "|---|---|---|---|---|---|---|---|"
for family in ${FAMILIES:-standard uGIMP cpGIMP CPDI}; do
  for beta in ${BETAS:-0 1e-4 1e-3 1e-2}; do
    dir="$out/${family}_$beta"
    cat > "$out/case.prm" <<PRM
include $root/prm/cooks_membrane.prm
set Kinematic assumption = plane strain
set Constants = F=${LOAD:-0.1}, uy_ref=25.19, uy_ref_mid=23.967, r_fit=4, tr=1, E=1, rho=1
subsection Time stepping
  set Integrator = quasi-static
  set Time step control = fixed
  set Time step = ${STEP:-0.1}
  set End time = 1
  set Damping coefficient = 0
end
subsection Implicit solver
  set Ghost penalty = $beta
end
subsection Shape functions
  set Family = $family
end
subsection Output
  set Directory = $dir
  set Interval = ${STEP:-0.1}
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Traction = 0; F/16*min(t/tr, 1)
    subsection Material
      set Model = neo-Hookean
      subsection Neo-Hookean
        set Young's modulus = E
        set Poisson's ratio = 0.3
      end
    end
  end
end
PRM
    rm -rf "$dir"
    start=$(date +%s.%N)
    "$mpm" "$out/case.prm" > "$dir.log" 2>&1 || true
    wall=$(python3 -c "import time; print(f'{time.time() - $start:.1f}')")
    python3 - "$dir/statistics.txt" "$family" "$beta" "$wall" <<'PY'
import sys
path, family, beta, wall = sys.argv[1:]
try:
    lines = [l.split() for l in open(path) if l.strip()]
except FileNotFoundError:
    lines = []
names = lines[0] if lines else []
rows = [dict(zip(names, r)) for r in lines[1:]]
rows = [r for r in rows if float(r["time"]) > 0]
def at(t):
    c = [float(r["uy_mid"]) for r in rows if abs(float(r["time"]) - t) < 1e-9]
    return f"{c[0]:.5f}" if c else "-"
end = f"{float(rows[-1]['uy_mid']):.5f}" if rows else "-"
reached = f"{float(rows[-1]['time']):.2f}" if rows else "0"
newton = sum(int(float(r["newton_iterations"])) for r in rows)
cuts = sum(int(float(r["step_cuts"])) for r in rows)
print(f"| {family} | {beta} | {at(0.4)} | {end} | {reached} | {newton} | {cuts} | {wall} |")
PY
  done
done
