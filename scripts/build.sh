#!/usr/bin/env bash
# Configure and build (Release) in build/. Usage: scripts/build.sh [targets...]
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
mkdir -p "$root/build"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > "$root/build/configure.log" \
  || { cat "$root/build/configure.log"; exit 1; }
cmake --build "$root/build" -j2 ${1:+--target "$@"}
