#!/usr/bin/env bash
# usage: check_bad_input.sh MPM CASE.prm WORKDIR
set -u
mpm=$1 case=$2 work=$3
rm -rf "$work" && mkdir -p "$work/results" && cd "$work" || exit 1
echo "results of an earlier run" > results/sentinel.txt
snapshot() { (cd results && ls -l --time-style=full-iso . && md5sum *) | md5sum; }
before=$(snapshot)

if [ -f "$case" ]; then
  status=$(sed -n 's/^# STATUS: *//p' "$case" | head -1)
  expect=$(sed -n 's/^# EXPECT: *//p' "$case" | head -1)
  [ -n "$(sed -n 's/^# COPY-TO-RESULTS//p' "$case")" ] && keep=1 || keep=0
else
  status=1 expect="Cannot open the parameter file" keep=0
fi

"$mpm" "$case" > stdout.txt 2> stderr.txt
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
