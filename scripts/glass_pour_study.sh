#!/usr/bin/env bash
# The pour into the glass (prm/glass_pour_2d.prm, prm/glass_pour_3d.prm,
# doc/benchmarks/glass_pour.md): makes the meshes with Gmsh from
# prm/glass/*.geo, runs standard MPM and the volumetric remedies
# (Volumetric smoothing = cell and node), prints the table of
# scripts/glass_pour_measures.py for the settled water and keeps each run
# in RESULTS/DIM/VARIANT (default results/glass_pour). With FIGURE=1 also
# draws doc/figures/glass_pour_2d.png (pressure snapshots, standard beside
# the remedies), doc/figures/glass_pour_3d.png (the 3D pour and the
# settled water) and doc/figures/glass_pour_3d.gif (the 3D pour).
# Usage: scripts/glass_pour_study.sh [RESULTS]
#        (MPM=..., RANKS=n, DIMS="2 3", VARIANTS="standard cell node",
#         FIGURE=1; about 2 min for 2D, 1.5 min per 3D variant on 2 cores)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
ranks=${RANKS:-2}
results=${1:-$root/results/glass_pour}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
py=/usr/bin/python3
for dim in ${DIMS:-2 3}; do
  dir="$results/${dim}d"
  mkdir -p "$dir"
  gmsh -"$dim" -format msh41 "$root/prm/glass/glass_${dim}d.geo" \
       -o "$dir/glass_${dim}d.msh" > "$dir/gmsh.log"
  for variant in ${VARIANTS:-standard cell node}; do
    rm -rf "${dir:?}/$variant"
    remedy=""
    [ "$variant" != standard ] && remedy="subsection Bodies
  subsection Body 0
    subsection Locking remedies
      set Volumetric smoothing = $variant
    end
  end
end"
    cat > "$dir/$variant.prm" <<PRM
include $root/prm/glass_pour_${dim}d.prm
subsection Output
  set Directory = $variant
end
$remedy
PRM
    start=$(date +%s)
    (cd "$dir" && mpirun -np "$ranks" "$mpm" "$variant.prm" > "$variant.log")
    echo "${dim}D $variant: $(( $(date +%s) - start )) s" >&2
  done
  runs=()
  for variant in ${VARIANTS:-standard cell node}; do runs+=("$dir/$variant"); done
  echo "${dim}D:"
  $py "$root/scripts/glass_pour_measures.py" "${runs[@]}"
  if [ "${FIGURE:-0}" = 1 ]; then
    if [ "$dim" = 2 ]; then
      $py "$root/scripts/plot_glass_pour.py" snapshots \
          "$root/doc/figures/glass_pour_2d.png" 0.2,0.35,2.5 "${runs[@]}"
    else
      $py "$root/scripts/plot_glass_pour.py" snapshots \
          "$root/doc/figures/glass_pour_3d.png" 0.3,0.8,2.5 "${runs[0]}"
      $py "$root/scripts/plot_glass_pour.py" animation \
          "$root/doc/figures/glass_pour_3d.gif" "${runs[0]}"
    fi
  fi
done
