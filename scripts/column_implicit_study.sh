#!/usr/bin/env bash
# Self-weight column by the quasi-static integrator under refinement, for
# every shape-function family (prm/column_compaction.prm: plane strain,
# laterally confined, l0 = 50 m, nu = 0, rho = 80, g = 10, gravity ramped
# over 20 load steps, 2x2 particles per body cell). Two deformations:
# large, E = 1 MPa (the elastic column compaction, 4% strain at the base,
# particles cross cells), and small, E = 1 GPa (0.004%). The grid is one
# cell of 1 m wide and l0/n high, n = 10, 20, 40, 80 (h = 5 ... 0.625 m),
# with one empty cell above the column. The domain families cut their
# domains at the grid's walls (Domain outside the grid = clamp).
# Writes OUT/table.txt (deformation, family, h, sigma_yy error: the RMS of
# sigma_yy - (-rho g (l0 - X)) over the particles divided by rho g l0, at
# the end; Newton iterations of the run; wall time) and prints it as a
# table.
# Figure: scripts/plot_column_implicit.py OUT doc/figures/column_implicit.png
# Usage: scripts/column_implicit_study.sh [OUT] [n values...]   (MPM=...)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
out=$(realpath -m "${1:-results/column_implicit}")
shift || true
mkdir -p "$out"
table="$out/table.txt"
echo "deformation family h sigma_yy_error newton wall" > "$table"
echo "| deformation | family | h [m] | sigma_yy error | Newton | wall [s] |"
echo "|---|---|---|---|---|---|"
for deformation in small large; do
  E=1e6
  [ $deformation = small ] && E=1e9
  for family in standard uGIMP cpGIMP CPDI CPDI2; do
    for n in ${@:-10 20 40 80}; do
      h=$(python3 -c "print(50/$n)")
      dir="$out/${deformation}_${family}_$n"
      cat > "$out/case.prm" <<PRM
include $root/prm/column_compaction.prm
set Constants = H=50, E=$E, nu=0, rho=80, g=10, tr=1
subsection Grid
  set Upper corner = 1, $(python3 -c "print(50 + $h)")
  set Subdivisions = 1, $((n + 1))
end
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Output
  set Directory = $dir
  set Interval = 0.05
end
subsection Bodies
  subsection Body 0
    set Subdivisions = 1, $n
  end
end
PRM
      rm -rf "$dir"
      start=$(date +%s.%N)
      "$mpm" "$out/case.prm" > "$dir.log" 2>&1
      wall=$(python3 -c "import time; print(f'{time.time() - $start:.2f}')")
      python3 - "$dir/statistics.txt" "$deformation" "$family" "$h" "$wall" "$table" <<'PY'
import sys
path, deformation, family, h, wall, table = sys.argv[1:]
lines = [l.split() for l in open(path) if l.strip()]
names = lines[0]
rows = [dict(zip(names, r)) for r in lines[1:]]
error = float(rows[-1]["sigma_yy_error"])
newton = sum(int(float(r["newton_iterations"])) for r in rows)
with open(table, "a") as f:
    f.write(f"{deformation} {family} {h} {error:.6e} {newton} {wall}\n")
print(f"| {deformation} | {family} | {float(h):g} | {error:.2e} | {newton} | {wall} |")
PY
    done
  done
done
