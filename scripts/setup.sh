#!/usr/bin/env bash
# Install what the project needs from Debian's packages, non-interactively.
# Idempotent: runs apt-get update and install only if something is missing.
set -euo pipefail
packages=(
  cmake make g++ perl numdiff
  libdeal.ii-dev libeigen3-dev libboost-test-dev libmuparser-dev
  openmpi-bin libopenmpi-dev
  python3 python3-numpy python3-matplotlib python3-pandas
  python3-sphinx python3-myst-parser
  gmsh
  # the BLAS of MUMPS's frontal matrices (the implicit direct solver):
  # with Debian's reference BLAS it factorises 3 to 10 times slower
  libopenblas0-serial
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO=sudo
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
