#!/usr/bin/env bash
# Installs the Debian packages the project builds with, if any are missing.
# Safe to run repeatedly; needs root (or sudo) only when something is missing.
set -euo pipefail
# clang and libclang-rt-14-dev: libFuzzer for the fuzz stage of scripts/test.sh;
# libembree-dev, libnanoflann-dev: the closest-point queries (stencil_runtime_distance);
# libcgal-dev: the initial control mesh from points (reconstruction/); libcgal-demo:
# its data.tar.gz holds the Stanford bunny of the fitting benchmark (bench/bunny_fit.cpp).
packages=(cmake g++ make libeigen3-dev libboost-dev libgmp-dev libmpfr-dev nlohmann-json3-dev catch2 libcli11-dev libtbb-dev libosd-dev
          clang libclang-rt-14-dev python3 libembree-dev libnanoflann-dev libcgal-dev libcgal-demo)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
