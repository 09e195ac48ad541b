#!/usr/bin/env bash
# Run mpm on a recompute_<benchmark>.prm case in the working directory and
# check with scripts/recompute_measures.py that the particle CSV files give
# the benchmark columns of statistics.txt. With --corrupt COLUMN, first
# check that they agree, then change COLUMN of the first particle of the
# last CSV by 1e-6 (relative and absolute) and require the check to fail (exit status 1):
# the comparison can see a wrong value.
# Usage: recompute_measures.sh MPM PRM NP [--corrupt COLUMN]
set -uo pipefail
mpm=$1 prm=$2 np=$3
root=$(cd "$(dirname "$0")/../.." && pwd)
rm -rf results screen.txt
run=("$mpm")
[ "$np" -gt 1 ] && run=(mpirun -np "$np" "$mpm")
"${run[@]}" "$prm" > screen.txt 2>&1 || { cat screen.txt; exit 1; }
check=(/usr/bin/python3 "$root/scripts/recompute_measures.py" results)
if [ "${4:-}" != --corrupt ]; then
  exec "${check[@]}"
fi
"${check[@]}" || exit 1
last=$(ls results/particles-*.csv | tail -1)
/usr/bin/python3 - "$last" "$5" <<'PY'
import sys
import pandas as pd
f, col = sys.argv[1], sys.argv[2]
d = pd.read_csv(f)
d.loc[0, col] = d.loc[0, col] * (1 + 1e-6) + 1e-6
d.to_csv(f, index=False, float_format="%.10g")
PY
"${check[@]}"
status=$?
if [ $status -eq 1 ]; then
  echo "OK: the changed $5 was detected"
  exit 0
fi
echo "FAIL: a changed $5 was not detected (status $status)"
exit 1
