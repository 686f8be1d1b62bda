#!/usr/bin/env bash
# Quick start, step 2: install dependencies, build from scratch, run the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
export BUILD_DIR=${BUILD_DIR:-build-test}
rm -rf "$BUILD_DIR"

# The Khronos glTF validator checks the animation's .glb files (npm registry), and
if ! command -v npm > /dev/null; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends nodejs npm
fi
# puppeteer-core drives Debian's chromium through the viewer page's browser test.
npm install --silent --no-save --no-package-lock --no-audit --no-fund \
  --prefix "$BUILD_DIR/npm" gltf-validator@2.0.0-dev.3.10 puppeteer-core@22.15.0
npm_dir=$(realpath "$BUILD_DIR/npm")  # BUILD_DIR may be relative or absolute
export MECHANIST_CMAKE_ARGS="-DMECHANIST_GLTF_VALIDATOR=$npm_dir/node_modules/gltf-validator \
-DMECHANIST_PUPPETEER=$npm_dir/node_modules"

scripts/build.sh
# Rendering needs an X display: a virtual one, kept from resetting between test processes.
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" \
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)"
