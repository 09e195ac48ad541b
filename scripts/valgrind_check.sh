#!/usr/bin/env bash
# Run a small case under valgrind's memcheck and print its summary.
#
# usage: [NP=2] scripts/valgrind_check.sh [CASE.prm]
#   CASE.prm  default: the base case of tests/ (2D, 64 particles on an 8 x 8
#             grid, 5 steps) with vtu and csv output switched on
# environment:
#   MPM    the executable (default build/mpm next to this script)
#   NP     MPI ranks (default 1): with NP > 1 every rank runs under its own
#          memcheck (mpirun -np NP valgrind ... mpm), one log per rank
#   LEAKS=1  also check leaks (--leak-check=full); leaks in our code count
#            as errors, the third-party ones are suppressed by
#            scripts/valgrind.supp
# Exit status: 0 if memcheck found no error, 1 otherwise (the full log is
# kept in the work folder, printed at the end).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
mpm=${MPM:-$root/build/mpm}
command -v valgrind > /dev/null ||
  { echo "valgrind_check.sh: valgrind is not installed" >&2; exit 1; }
[ -x "$mpm" ] || { echo "valgrind_check.sh: no executable $mpm" >&2; exit 1; }

work=$(mktemp -d /tmp/mpm-valgrind.XXXXXX)
if [ $# -ge 1 ]; then
  case_file=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
else
  case_file=$work/case.prm
  cat > "$case_file" <<EOF
include $root/tests/base_case.prm.inc
subsection Output
  set Write vtu = true
  set Write csv = true
end
EOF
fi

# OpenMPI is initialised even in serial runs; as root it needs these.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
leak_args=(--leak-check=no)
[ "${LEAKS:-0}" = 1 ] &&
  leak_args=(--leak-check=full --show-leak-kinds=definite,indirect
             --errors-for-leak-kinds=definite,indirect)
np=${NP:-1}
launcher=()
[ "$np" -gt 1 ] && launcher=(mpirun -np "$np")
export OMPI_MCA_rmaps_base_oversubscribe=1
rc=0
(cd "$work" && "${launcher[@]}" valgrind --tool=memcheck --error-exitcode=1 \
   --num-callers=40 --track-origins=yes "${leak_args[@]}" \
   --suppressions="$root/scripts/valgrind.supp" \
   --log-file=valgrind.%p.log \
   "$mpm" "$case_file" > mpm_stdout.txt 2> mpm_stderr.txt) || rc=$?
for log in "$work"/valgrind.*.log; do
  echo "${log##*/}:"
  # A forked child that exec'd another program (OpenMPI's singleton start
  # without mpirun) leaves a log with a header only: nothing to report.
  grep -E "ERROR SUMMARY|definitely lost|indirectly lost|suppressed:" "$log" |
    sed 's/^==[0-9]*== */  /' ||
    echo "  (no summary: a child process that ran another program)"
done
echo "full logs: $work/valgrind.<pid>.log"
[ $rc = 0 ] && echo "valgrind_check.sh: OK" || echo "valgrind_check.sh: FAIL (status $rc)"
exit $rc
