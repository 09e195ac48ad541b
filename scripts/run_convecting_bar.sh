#!/usr/bin/env bash
# Convecting bar (doc/benchmarks/convecting_bar.md; prm/convecting_bar.prm:
# a 1D bar in quasi-static equilibrium that travels 2 L at v0): standard
# MPM, the 1D convection correction of the stress only
# (Body force correction = false) and the full correction, and the
# particle-domain families uGIMP, cpGIMP, CPDI and CPDI2 (without
# correction), with 2 and 4 particles per cell, then the table and the plot.
# Statistics every step, no particle files.
# Usage: scripts/run_convecting_bar.sh [FOLDER] [FLIP fraction]
# (default results/convecting-bar, and the prm's PIC, 0).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/convecting-bar}
flip=${2:-0}
mkdir -p "$out"
cd "$out"
for ppc in 2 4; do
  for variant in standard stress-only correction uGIMP cpGIMP CPDI CPDI2; do
    filter="convection correction" body_force=true family=standard
    case "$variant" in
      standard) filter=none ;;
      stress-only) body_force=false ;;
      correction) ;;
      *) filter=none family=$variant ;;
    esac
    name=ppc$ppc-$variant
    cat > "$name.prm" <<PRM
include $root/prm/convecting_bar.prm
subsection Shape functions
  set Family = $family
end
subsection Time stepping
  set FLIP fraction = $flip
end
subsection Output
  set Directory = $name
  set Interval = 0
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Particles per direction = $ppc
    subsection Locking remedies
      set Stress filter = $filter
      set Body force correction = $body_force
    end
  end
end
PRM
    "$root/build/mpm" "$name.prm" > "$name.log"
  done
done
/usr/bin/python3 "$root/scripts/plot_convecting_bar.py" "$out" "$out/convecting_bar.png"
