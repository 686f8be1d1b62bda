#!/usr/bin/env bash
# Installs exactly the Debian 12 packages mechanist needs to build and test.
# Skips apt entirely when everything is already installed.
set -euo pipefail

packages=(
  build-essential cmake
  libeigen3-dev libboost-graph-dev nlohmann-json3-dev libcli11-dev libfmt-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libcgal-dev libgmp-dev libmpfr-dev
  libfcl-dev libceres-dev
  libvtk9-dev libx11-dev xvfb xauth ffmpeg
  libocct-data-exchange-dev libocct-ocaf-dev libocct-modeling-algorithms-dev
  libocct-modeling-data-dev libocct-foundation-dev
  libmujoco-dev liburdfdom-tools
  libjs-three chromium
  clang libclang-rt-14-dev
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

sudo=""
if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
echo "install-deps: installing ${missing[*]}"
$sudo apt-get update -qq
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
