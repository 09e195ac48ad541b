#!/usr/bin/env bash
# usage: check_bad_input.sh MPM CASE.prm WORKDIR [NPROC]
set -u
mpm=$1 case=$2 work=$3 np=${4:-1}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
rm -rf "$work" && mkdir -p "$work/results" && cd "$work" || exit 1
echo "results of an earlier run" > results/sentinel.txt
# every file and folder below results/, with times and contents
snapshot() { (cd results && ls -lR --time-style=full-iso . &&
              find . -type f -print0 | sort -z | xargs -0 md5sum) | md5sum; }

if [ -f "$case" ]; then
  status=$(sed -n 's/^# STATUS: *//p' "$case" | head -1)
  expect=$(sed -n 's/^# EXPECT: *//p' "$case" | head -1)
  before_run=$(sed -n 's/^# BEFORE: *//p' "$case" | head -1)
  [ -n "$(sed -n 's/^# COPY-TO-RESULTS//p' "$case")" ] && keep=1 || keep=0
elif [ -d "$case" ]; then
  status=1 expect="is a directory, not a file" keep=0 before_run=
else
  status=1 expect="Cannot open the parameter file" keep=0 before_run=
fi
# `# BEFORE: FILE` (next to the case): a run that must succeed first, e.g.
# one that leaves the checkpoint a restart is then tried from
if [ -n "$before_run" ]; then
  "$mpm" "$(dirname "$case")/$before_run" > before.txt 2>&1 \
    || { echo "FAIL: the run before the case failed"; cat before.txt; exit 1; }
fi
before=$(snapshot)

if [ "$np" -gt 1 ]; then
  # under MPI every rank must stop: a hang is a failure (timeout)
  timeout 120 mpirun -np "$np" "$mpm" "$case" > stdout.txt 2> stderr.txt
else
  "$mpm" "$case" > stdout.txt 2> stderr.txt
fi
rc=$?
cat stderr.txt
if [ "$rc" != "$status" ]; then
  echo "FAIL: exit status $rc, expected $status"; cat stdout.txt; exit 1
fi
if ! grep -qF -- "$expect" stderr.txt; then
  echo "FAIL: message does not contain: $expect"; exit 1
fi
if [ "$(cat results/sentinel.txt)" != "results of an earlier run" ]; then
  echo "FAIL: the existing output was changed"; exit 1
fi
if [ "$status" = 1 ] && [ "$(snapshot)" != "$before" ]; then
  echo "FAIL: an input error wrote into the output directory"; ls -la results; exit 1
fi
if [ "$keep" = 1 ] && [ ! -s results/statistics.txt ]; then
  echo "FAIL: output written before the error is missing"; exit 1
fi
echo "OK: exit $rc with the expected message"
