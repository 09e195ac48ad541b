#!/usr/bin/env bash
# One command from a fresh Debian 12 machine: install, build, run the whole
# test suite with ctest (build about 15 minutes, tests about 8 minutes, on 2 cores).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
"$root/scripts/setup.sh"
"$root/scripts/build.sh"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
cd "$root/build"
ctest --output-on-failure -j2 "$@"
