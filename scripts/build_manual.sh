#!/usr/bin/env bash
# Build the manual (HTML) from doc/ with Sphinx and MyST, warnings as
# errors: a broken link, a missing figure or a page outside the table of
# contents fails the build. The parameter reference is generated from the
# programs themselves (mpm/mpm-fe --print-parameters DIM json), so it
# cannot drift from the code.
# Usage: scripts/build_manual.sh [OUT]   (default build/manual; the HTML
# is OUT/html/index.html)
# Environment: MPM, MPM_FE (the executables, default build/mpm and
# build/mpm-fe).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/build/manual}
mpm=${MPM:-$root/build/mpm}
mpm_fe=${MPM_FE:-$root/build/mpm-fe}
for p in "$mpm" "$mpm_fe"; do
  [ -x "$p" ] || { echo "build_manual: $p not found; build first (scripts/build.sh)" >&2; exit 1; }
done
command -v sphinx-build > /dev/null || {
  echo "build_manual: sphinx-build not found; run scripts/setup.sh" >&2; exit 1; }

src="$out/src"
rm -rf "$src" "$out/html"
mkdir -p "$src/reference" "$out/json"
cp -r "$root/doc/." "$src/"

# the parameter reference, one page per program, every dimension merged
for d in 1 2 3; do "$mpm" --print-parameters $d json > "$out/json/mpm-$d.json"; done
for d in 2 3; do "$mpm_fe" --print-parameters $d json > "$out/json/mpm-fe-$d.json"; done
ref="$root/scripts/parameter_reference.py"
/usr/bin/python3 "$ref" --out "$src/reference/mpm_parameters.md" \
  --title "Parameters of mpm" \
  --intro "Every entry of an \`mpm\` parameter file, in the order \`mpm --print-parameters\` prints them, generated from the program when the manual is built. Bodies are numbered: the entries of \`Body 0\` exist for every body up to \`Number of bodies\`. Where an entry differs between dimensions, each is listed. The file format, expressions and constants are explained in [the parameter file](../parameter_file.md)." \
  1:"$out/json/mpm-1.json" 2:"$out/json/mpm-2.json" 3:"$out/json/mpm-3.json"
/usr/bin/python3 "$ref" --out "$src/reference/mpm_fe_parameters.md" \
  --title "Parameters of mpm-fe" \
  --intro "Every entry of an \`mpm-fe\` parameter file (the finite-element reference solver, see [its page](../fe_reference.md)), generated from the program when the manual is built." \
  2:"$out/json/mpm-fe-2.json" 3:"$out/json/mpm-fe-3.json"

sphinx-build -q -W --keep-going -b html "$src" "$out/html"
echo "manual: $out/html/index.html"
