#!/usr/bin/env bash
# The vibrating cantilever (doc/benchmarks/cantilever.md) over its aspect
# ratio and Poisson's ratio: the period T of standard MPM and of the
# assumed-stress filter (mass and compliance metrics) against the FE
# reference period T_FE of the same beam, at DEPTH_CELLS (default 2) cells
# through the depth with 2x2 particles per cell, plane stress.
# The depth stays H = 0.1 m and the cell h = H/DEPTH_CELLS; the length is
# L = (L/H) H, so a longer beam has more cells along it. Each beam starts in its first
# Euler-Bernoulli mode (tip speed 0.05 m/s) and runs for about three of its
# periods; T is the mean interval between upward zero crossings of the tip
# (scripts/beam_period.py). T_FE: mpm-fe's modal analysis of the same beam
# (Q2, refined 4 times from one cell through the depth).
# DIM=3: the beam of square cross-section H x H, DEPTH_CELLS cells through
# both its depth and its width with 2x2x2 particles per cell, bending in y;
# T_FE from Q3 refined twice from one cell through the section (Q2 there
# is 1% short at nu = 0.49: doc/benchmarks/cantilever.md, "In 3D").
# Writes OUT/table.txt: L/H nu variant T T_FE T/T_FE.
# Environment: RATIOS (default "4 10 20 40"), NUS (default "0 0.3 0.49"),
# VARIANTS (default "standard filter-mass filter-compliance"), JOBS (runs at
# a time, default 2), DEPTH_CELLS (default 2), DIM (default 2). About 4
# minutes on 2 cores in 2D.
# Usage: scripts/cantilever_aspect_study.sh [OUT]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=$(realpath -m "${1:-results/cantilever_aspect}")
ratios=${RATIOS:-"4 10 20 40"}
nus=${NUS:-"0 0.3 0.49"}
variants=${VARIANTS:-"standard filter-mass filter-compliance"}
jobs=${JOBS:-2}
n=${DEPTH_CELLS:-2}
dim=${DIM:-2}
mpm=${MPM:-$root/build/mpm}
mpm_fe=${MPM_FE:-$root/build/mpm-fe}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
mkdir -p "$out"
H=0.1 E=1e7 rho=1000

length() { /usr/bin/python3 -c "print(round($1*$H, 12))"; }
# T_EB = 2 pi / (3.51602 sqrt(E H^2 / (12 rho L^4)))
t_eb() { /usr/bin/python3 -c "import math; L=$1*$H; print(2*math.pi/(3.51602*math.sqrt($E*$H**2/(12*$rho*L**4))))"; }

fe_case() { # ratio nu
  local r=$1 nu=$2 dir="$out/fe_${1}_${2}" L
  L=$(length "$r")
  mkdir -p "$dir"
  if [ "$dim" = 2 ]; then
    cat > "$dir/case.prm" <<PRM
include $root/prm/fe_cantilever_modal.prm
set Constants = L=$L, H=$H, E=$E, nu=$nu, rho=$rho
subsection Geometry
  set Upper corner = $L, $H
  set Subdivisions = $r, 1
end
subsection Discretisation
  set Refinements = 0, 1, 2, 3, 4
end
PRM
  else
    cat > "$dir/case.prm" <<PRM
set Dimension = 3
set Constants = L=$L, H=$H, E=$E, nu=$nu, rho=$rho
subsection Geometry
  set Lower corner = 0, 0, 0
  set Upper corner = $L, $H, $H
  set Subdivisions = $r, 1, 1
end
subsection Material
  set Density = rho
  subsection Linear elastic
    set Young's modulus = E
    set Poisson's ratio = nu
  end
end
subsection Boundary conditions
  set Clamped boundary ids = 0
end
subsection Discretisation
  set Formulation = displacement
  set Polynomial degree = 3
  set Refinements = 1, 2
end
subsection Analysis
  set Type = modal
  set Number of modes = 3
end
PRM
  fi
  cat >> "$dir/case.prm" <<PRM
subsection Analysis
  set Required relative change = 0
end
subsection Output
  set Directory = $dir/output
  set Write vtu = false
end
PRM
  (cd "$dir" && "$mpm_fe" case.prm > log.txt)
  awk -F, 'NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
           { T = $c["T_1"] } END { print T }' "$dir/output/refinement_study.csv"
}

mpm_case() { # ratio nu variant
  local r=$1 nu=$2 v=$3 filter=none metric=mass
  case $v in
    filter-mass) filter="assumed stress" ;;
    filter-compliance) filter="assumed stress"; metric=compliance ;;
  esac
  local dir="$out/mpm_${r}_${nu}_${v}" T_eb end L
  T_eb=$(t_eb "$r")
  L=$(length "$r")
  end=$(/usr/bin/python3 -c "print(3.3*$T_eb)")
  mkdir -p "$dir"
  if [ "$dim" = 2 ]; then
    cat > "$dir/case.prm" <<PRM
include $root/prm/cantilever_beam.prm
set Constants = L=$L, H=$H, E=$E, nu=$nu, rho=$rho, vtip=0.05, b=1.87510407
subsection Grid
  set Upper corner = $(/usr/bin/python3 -c "print($L + 0.2)"), 0.3
  set Subdivisions = $((n * r + 2 * n)), $((5 * n))
end
subsection Bodies
  subsection Body 0
    set Upper corner = $L, $H
    set Subdivisions = $((n * r)), $n
  end
end
PRM
  else
    # the 2D file's entries in 3D: the grid reaches H beside the section
    # in z, the velocity is the same first mode in y
    cat > "$dir/case.prm" <<PRM
set Dimension = 3
set Constants = L=$L, H=$H, E=$E, nu=$nu, rho=$rho, vtip=0.05, b=1.87510407
set Benchmark = cantilever
subsection Grid
  set Lower corner = 0, -0.2, -$H
  set Upper corner = $(/usr/bin/python3 -c "print($L + 0.2)"), 0.3, $(/usr/bin/python3 -c "print(2 * $H)")
  set Subdivisions = $((n * r + 2 * n)), $((5 * n)), $((3 * n))
end
subsection Boundary conditions
  set Fixed boundary ids = 0
end
subsection Output
  set Write vtu = false
  set Write csv = false
end
subsection Bodies
  subsection Body 0
    set Lower corner = 0, 0, 0
    set Upper corner = $L, $H, $H
    set Subdivisions = $((n * r)), $n, $n
    set Particles per direction = 2
    set Initial velocity = 0; vtip*(cosh(b*x/L) - cos(b*x/L) - 0.734096*(sinh(b*x/L) - sin(b*x/L))) / (cosh(b) - cos(b) - 0.734096*(sinh(b) - sin(b))); 0
    subsection Material
      set Model = linear elastic
      set Density = rho
      subsection Linear elastic
        set Young's modulus = E
        set Poisson's ratio = nu
      end
    end
  end
end
PRM
  fi
  cat >> "$dir/case.prm" <<PRM
subsection Time stepping
  set End time = $end
end
subsection Output
  set Directory = $dir/output
  set Interval = $(/usr/bin/python3 -c "print($T_eb/400)")
end
subsection Bodies
  subsection Body 0
    subsection Locking remedies
      set Stress filter = $filter
      set Filter metric = $metric
    end
  end
end
PRM
  (cd "$dir" && "$mpm" case.prm > log.txt)
  "$root/scripts/beam_period.py" "$dir/output" "$L" $H $E $rho |
    sed 's/^T = \([0-9.]*\) s.*/\1/'
}
export -f mpm_case t_eb length
export root out H E rho mpm n dim

# the FE references first (serial: each is a direct solve)
declare -A T_FE
for r in $ratios; do
  for nu in $nus; do
    T_FE[$r,$nu]=$(fe_case "$r" "$nu")
    echo "L/H = $r, nu = $nu: T_FE = ${T_FE[$r,$nu]} s"
  done
done

# the MPM runs, JOBS at a time; each prints "ratio nu variant T"
list="$out/runs.txt"
: > "$list"
for r in $ratios; do for nu in $nus; do for v in $variants; do
  echo "$r $nu $v" >> "$list"
done; done; done
xargs -r -P "$jobs" -L 1 bash -c 'echo "$0 $1 $2 $(mpm_case "$0" "$1" "$2")"' \
  < "$list" > "$out/periods.txt"

table="$out/table.txt"
echo "L/H nu variant T T_FE T/T_FE" > "$table"
sort -k1,1n -k2,2n -k3,3 "$out/periods.txt" | while read -r r nu v T; do
  fe=${T_FE[$r,$nu]}
  /usr/bin/python3 -c "print('$r $nu $v %.5f %.5f %.4f' % ($T, $fe, $T/$fe))"
done >> "$table"
column -t "$table"
