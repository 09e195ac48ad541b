#!/usr/bin/env bash
# The convecting bar as a 2D strip (prm/convecting_strip.prm): RMS stress
# error after 2L of travel (and its largest value over the run) for
# standard MPM, uGIMP and CPDI, each without filter, with the
# Pian-Sumihara filter and with the enriched filter (doc/theory/assumed_stress_filter.md).
# Usage: scripts/convecting_strip_study.sh [OUT] (default
# results/convecting-strip). About 1 min.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/results/convecting-strip}
mkdir -p "$out"
cd "$out"
echo "family filter sigma_rms_end sigma_rms_max" > table.txt
for family in standard uGIMP CPDI; do
  for filter in none Pian-Sumihara enriched; do
    name=$family-$filter
    remedy="none" field=Pian-Sumihara
    [ "$filter" != none ] && remedy="assumed stress" field=$filter
    cat > "$name.prm" <<PRM
include $root/prm/convecting_strip.prm
subsection Shape functions
  set Family = $family
  set Domain outside the grid = clamp
end
subsection Output
  set Directory = $name
end
subsection Bodies
  subsection Body 0
    subsection Locking remedies
      set Stress filter = $remedy
      set Filter field = $field
    end
  end
end
PRM
    "$root/build/mpm" "$name.prm" > "$name.log"
    awk -v f="$family" -v g="$filter" '
      NR == 1 { for (i = 1; i <= NF; ++i) c[$i] = i; next }
      { s = $c["sigma_rms_error"]; if (s > m) m = s; last = s }
      END { printf "%s %s %.4f %.4f\n", f, g, last, m }' \
      "$name/statistics.txt" >> table.txt
  done
done
column -t table.txt
