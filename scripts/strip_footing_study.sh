#!/usr/bin/env bash
# Smooth rigid strip footing on undrained clay (prm/strip_footing.prm):
# standard MPM and Volumetric smoothing = cell (theta-bar) on grids h =
# 0.25, 0.125, 0.0625 (B = 1), loaded by the footing's settlement in
# steps of 0.01 B up to 0.5 B. Writes OUT/<variant>_<h>.txt (settlement/B,
# q/c_u = -2 reaction_y/(B c_u)) and prints, per run, q/c_u at settlement
# 0.05, 0.1, 0.2 B and at the last converged step, its largest value (with
# Geometry = fixed the limit load of the discretization) and where, the
# settlement reached, the Newton iterations and the wall time. A run whose Newton iteration
# fails after every step cut stops there; its curve ends at that point.
# Prandtl's limit: q/c_u = 2 + pi = 5.142. Figure:
# scripts/plot_strip_footing.py OUT doc/figures/strip_footing.png (the
# validation suite's part strip_footing runs both).
# FAMILIES (default "standard") lists the shape-function families to run
# each variant with; a family other than standard is named in the
# variant, e.g. theta-bar-cpGIMP; their domains are cut at the grid's
# walls (Domain outside the grid = clamp). REMEDIES (default "standard
# theta-bar") lists the variants; node is Volumetric smoothing = node (the
# node average); filter is the assumed-stress filter with
# the compliance metric; theta-bar-split is theta-bar with Implicit
# solver/Preconditioner = AMG with cell pressure (the same curve, fewer
# GMRES iterations). GHOST (default: the parameter file's 0.01) sets
# Implicit solver/Ghost penalty; theta-bar and node run with Particle
# volume = smoothed unless PARTICLE_VOLUME=own. MIN_J=1 writes the particle tables
# and adds the smallest volume ratio V/V0 of the soil at 0.2 B.
# GEOMETRY=fixed runs with Implicit solver/Geometry = fixed (equilibrium
# in the undeformed shape) and appends -fixed to the variant's name;
# GEOMETRY="small strain" adds the linearized kinematics (the
# small-deformation analysis) and appends -small-strain. END (default 0.5) is the last
# settlement / B, STEP (default 0.01) the load step / B, SOLVER (default
# automatic) the Implicit solver/Linear solver. GRID=graded takes each h as the cell size on the region
# of the collapse mechanism only, the cells growing towards the far walls
# (scripts/make_strip_footing_grid.py; the soil then is that grid's
# cells below its surface), and appends -graded to the variant's name;
# EDGE (with GRID=graded) refines the cells around the footing's edge to
# that size and appends -edge<EDGE>.
# STIFFNESS (default the parameter file's 100) sets the soil's E / c_u and
# appends -E<value> to the variant's name.
# Usage: scripts/strip_footing_study.sh [OUT] [h values...]   (MPM=...)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
out=$(realpath -m "${1:-results/strip_footing}")
shift || true
mkdir -p "$out"
if [ -n "${MIN_J:-}" ]; then
  echo "| variant | h | q/c_u at 0.05 B | 0.1 B | 0.2 B | last | largest (at settlement / B) | settlement reached / B | Newton | wall [s] | smallest V/V0 at 0.2 B |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
else
  echo "| variant | h | q/c_u at 0.05 B | 0.1 B | 0.2 B | last | largest (at settlement / B) | settlement reached / B | Newton | wall [s] |"
  echo "|---|---|---|---|---|---|---|---|---|---|"
fi
for h in ${@:-0.25 0.125 0.0625}; do
  read -r nx ny ns nf <<< "$(python3 -c "print(round(5/$h), round(6.25/$h), round(5/$h), round(0.5/$h))")"
  for family in ${FAMILIES:-standard}; do
  for remedy in ${REMEDIES:-standard theta-bar}; do
    smoothing=none filter=none
    preconditioner=AMG
    [ $remedy = theta-bar ] && smoothing=cell
    [ $remedy = node ] && smoothing=node
    [ $remedy = theta-bar-split ] && smoothing=cell preconditioner="AMG with cell pressure"
    [ $remedy = filter ] && filter="assumed stress"
    variant=$remedy
    [ $family = standard ] || variant=$remedy-$family
    [ "${GEOMETRY:-updated}" = fixed ] && variant=$variant-fixed
    [ "${GEOMETRY:-updated}" = "small strain" ] && variant=$variant-small-strain
    stiffness=""
    if [ -n "${STIFFNESS:-}" ]; then
      variant=$variant-E$STIFFNESS
      stiffness="subsection Material
      subsection Von Mises plasticity
        set Young's modulus = $STIFFNESS*cu
      end
    end"
    fi
    grid_section="subsection Grid
  set Subdivisions = $nx, $ny
end"
    soil_section="set Subdivisions = $ns, $ns"
    footing_cells=$nf
    footing_top=$(python3 -c "print(5 + $h)")
    if [ "${GRID:-uniform}" = graded ]; then
      variant=$variant-graded
      footing_top=$(python3 -c "print(5 + ${EDGE:-$h})")
      footing_cells=$(python3 -c "print(max(4 * $nf, round(1 / ${EDGE:-$h})))")
      mesh=$out/mesh_$h${EDGE:+_$EDGE}
      [ -n "${EDGE:-}" ] && variant=$variant-edge$EDGE
      mkdir -p "$mesh"
      python3 "$root/scripts/make_strip_footing_grid.py" "$mesh/grid.ucd" \
        "$mesh/soil.ucd" "$h" ${EDGE:-} > /dev/null
      grid_section="subsection Grid
  set Type = mesh file
  set Mesh file = $mesh/grid.ucd
end"
      soil_section="set Geometry = mesh file
    set Mesh file = $mesh/soil.ucd"
    fi
    dir="$out/${variant}_$h"
    cat > "$out/case.prm" <<PRM
include $root/prm/strip_footing.prm
$grid_section
subsection Time stepping
  set End time = ${END:-0.5}
  set Time step = ${STEP:-0.01}
end
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Output
  set Directory = $dir
  set Interval = ${STEP:-0.01}
  set Write vtu = false
  set Write csv = $([ -n "${MIN_J:-}" ] && echo true || echo false)
end
subsection Implicit solver
  set Preconditioner = $preconditioner
  set Linear solver = ${SOLVER:-automatic}
  set Ghost penalty = ${GHOST:-0.01}
  set Geometry = ${GEOMETRY:-updated}
end
subsection Bodies
  subsection Body 0
    $soil_section
    $stiffness
    subsection Locking remedies
      set Volumetric smoothing = $smoothing
      set Stress filter = $filter
      set Filter metric = compliance
      set Particle volume = ${PARTICLE_VOLUME:-smoothed}
    end
  end
  subsection Body 1
    set Upper corner = 0.5, $footing_top
    set Subdivisions = $footing_cells, 1
  end
end
PRM
    rm -rf "$dir"
    start=$(date +%s.%N)
    "$mpm" "$out/case.prm" > "$dir.log" 2>&1 || true
    wall=$(python3 -c "import time; print(f'{time.time() - $start:.1f}')")
    python3 - "$dir/statistics.txt" "$out/${variant}_$h.txt" "$variant" "$h" "$wall" <<'PY'
import sys
path, curve, variant, h, wall = sys.argv[1:]
lines = [l.split() for l in open(path) if l.strip()]
names = lines[0]
rows = [dict(zip(names, r)) for r in lines[1:]]
B, cu = 1.0, 1e4
pts = [(float(r["time"]) / B, -2 * float(r["reaction_y"]) / (B * cu)) for r in rows]
with open(curve, "w") as f:
    f.write("settlement_over_B q_over_cu\n")
    for s, q in pts:
        f.write(f"{s:.4f} {q:.5f}\n")
def at(s):
    c = [q for x, q in pts if abs(x - s) < 1e-9]
    return f"{c[0]:.3f}" if c else "-"
newton = sum(int(float(r["newton_iterations"])) for r in rows)
# the soil's smallest V/V0 at 0.2 B, from its particle table (MIN_J=1)
import csv, os
min_j = ""
# (one table per step from t = 0, as statistics.txt's rows)
index = [i for i, r in enumerate(rows) if abs(float(r["time"]) - 0.2) < 1e-9]
table = os.path.join(os.path.dirname(path), "particles-%05d.csv" % index[0]) if index else ""
if table and os.path.exists(table):
    j = [float(r["volume"]) / float(r["volume0"]) for r in csv.DictReader(open(table))
         if int(float(r["body"])) == 0]
    min_j = f" {min(j):.3f} |"
peak = max(pts, key=lambda p: p[1])
print(f"| {variant} | {h} | {at(0.05)} | {at(0.1)} | {at(0.2)} | "
      f"{pts[-1][1]:.3f} | {peak[1]:.3f} ({peak[0]:.2f}) | {pts[-1][0]:.2f} | "
      f"{newton} | {wall} |{min_j}")
PY
  done
  done
done
