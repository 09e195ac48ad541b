#!/usr/bin/env bash
# The parameter file of the throughput case (prm/throughput_2d.prm or _3d)
# for one variant, on standard output; scripts/throughput.sh and
# scripts/instructions_per_update.sh run it.
# Usage: scripts/throughput_case.sh DIM CELLS VARIANT (variants: see
# scripts/throughput.sh)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
dim=$1 cells=$2 variant=$3
family=standard remedy="" material="" lower=-0.25 upper=1.25 grid=$((cells * 3 / 2)) interval=0
at_setup=true
case "$variant" in
  standard) ;;
  unbalanced) at_setup=false ;;
  corner) upper=2.25 grid=$((cells * 5 / 2)) at_setup=false ;;
  corner-balanced) upper=2.25 grid=$((cells * 5 / 2)) interval=50 ;;
  wide) lower=-1 upper=2 grid=$((cells * 3)) ;;
  filter) remedy="set Stress filter = assumed stress" ;;
  theta-bar) remedy="set Volumetric smoothing = cell" ;;
  uGIMP|cpGIMP|CPDI|CPDI2) family=$variant ;;
  neo-Hookean) material="set Model = neo-Hookean
      subsection Neo-Hookean
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end" ;;
  von-Mises) material="set Model = von Mises plasticity
      subsection Von Mises plasticity
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
        set Yield stress = 2e2
      end" ;;
  *) echo "unknown variant '$variant'" >&2; exit 1 ;;
esac
corner=$upper low=$lower
[ "$dim" = 3 ] && corner="$upper, $upper" low="$lower, $lower"
cat <<PRM
include $root/prm/throughput_${dim}d.prm
subsection Grid
  set Lower corner = $lower, $low
  set Upper corner = $upper, $corner
  set Subdivisions = $grid
end
subsection Load balancing
  set Balance at set-up = $at_setup
  set Repartition interval (steps) = $interval
end
subsection Shape functions
  set Family = $family
end
subsection Bodies
  subsection Body 0
    set Subdivisions = $cells
    subsection Locking remedies
      $remedy
    end
    subsection Material
      $material
    end
  end
end
PRM

