#!/usr/bin/env bash
# The memory figures behind the resource estimate (solver/
# resource_estimate.cc): bytes per grid cell, per particle (standard and
# CPDI) and per body cell of the implicit step, from what mpm reports as
# allocated after one step on one rank, each case less a tiny one's base.
# Each line also prints mpm --validate's estimate, which must stay below
# the measured figure (it is a lower bound).
# Usage: scripts/memory_figures.sh   (about 3 minutes, 3 GB)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"

# case DIM GRID_CELLS BODY_CELLS PPD FAMILY INTEGRATOR: a unit body in a
# grid [0, 1.25]^dim (fixed base and slip sides when implicit)
case_prm() {
  local dim=$1 g=$2 b=$3 ppd=$4 family=$5 integrator=$6
  local zeros ones up gravity
  zeros=$(/usr/bin/python3 -c "print(', '.join(['0']*$dim))")
  ones=$(/usr/bin/python3 -c "print(', '.join(['1']*$dim))")
  up=$(/usr/bin/python3 -c "print(', '.join(['1.25']*$dim))")
  gravity=$(/usr/bin/python3 -c "print('; '.join(['0']*($dim-1)+['-10']))")
  cat <<P
set Dimension = $dim
subsection Grid
  set Lower corner = $zeros
  set Upper corner = $up
  set Subdivisions = $g
end
subsection Boundary conditions
  set Fixed boundary ids = $((2 * dim - 2))
$( [ "$dim" -gt 1 ] && echo "  set Slip boundary ids = $(/usr/bin/python3 -c "print(', '.join(str(i) for i in range(2*$dim-2)))")" )
end
subsection Shape functions
  set Family = $family
end
subsection Time stepping
  set Integrator = $integrator
$( if [ "$integrator" = explicit ]; then
     echo "  set Maximum number of steps = 1"
   else
     printf '  set Time step control = fixed\n  set Time step = 0.01\n  set End time = 0.01\n'
   fi )
end
subsection Output
  set Directory = out
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = $zeros
    set Upper corner = $ones
    set Subdivisions = $b
    set Particles per direction = $ppd
    set Body force = $gravity
    subsection Material
      set Model = linear elastic
      set Density = 1000
      subsection Linear elastic
        set Young's modulus = 1e6
        set Poisson's ratio = 0.3
      end
    end
  end
end
P
}

# allocated bytes after the run, and the --validate estimate
measure() {
  case_prm "$@" > case.prm
  local estimate allocated
  estimate=$("$mpm" --validate case.prm | sed -n 's/.*memory estimate: at least \([^ ]*\) GB.*/\1/p')
  allocated=$("$mpm" case.prm | sed -n 's/.*at the end \([^ ]*\) MB allocated.*/\1/p')
  echo "$allocated $estimate"
}

# label items base_MiB measured_MiB estimate_GB other_MiB: prints the
# bytes per item and sets $bytes
per_item() {
  bytes=$(/usr/bin/python3 -c "print(round((float('$4') - float('$3') - float('$6')) * 2**20 / float('$2')))")
  /usr/bin/python3 -c "
print(f'{\"$1\":40s} {$bytes:6d} bytes each   (allocated {float(\"$4\")*2**20/1e9:6.3f} GB, estimate {float(\"$5\"):6.3f} GB)')"
}

for dim in 1 2 3; do
  read -r base _ <<< "$(measure $dim 4 1 1 standard explicit)"
  case $dim in
    1) g=1000000; p=500000; ib=100000 ;;
    2) g=1024;    p=512;    ib=256 ;;
    3) g=96;      p=64;     ib=32 ;;
  esac
  read -r grid est <<< "$(measure $dim $g 1 1 standard explicit)"
  cells=$(/usr/bin/python3 -c "print($g**$dim)")
  per_item "${dim}D grid cell" "$cells" "$base" "$grid" "$est" 0
  cell_mib=$(/usr/bin/python3 -c "print(($grid - $base) / $cells)")
  pgrid=$(/usr/bin/python3 -c "print(int($p * 1.5))")
  for family in standard CPDI; do
    read -r m est <<< "$(measure $dim $pgrid $p 2 $family explicit)"
    n=$(/usr/bin/python3 -c "print(($p * 2)**$dim)")
    other=$(/usr/bin/python3 -c "print($cell_mib * $pgrid**$dim)")
    per_item "${dim}D particle ($family)" "$n" "$base" "$m" "$est" "$other"
    [ "$family" = standard ] && particle_bytes=$bytes
  done
  read -r m est <<< "$(measure $dim $((ib * 5 / 4)) $ib 2 standard quasi-static)"
  n=$(/usr/bin/python3 -c "print($ib**$dim)")
  other=$(/usr/bin/python3 -c "print($cell_mib * ($ib*5//4)**$dim + ($ib*2)**$dim * $particle_bytes / 2**20)")
  per_item "${dim}D implicit body cell (matrix, AMG)" "$n" "$base" "$m" "$est" "$other"
done
