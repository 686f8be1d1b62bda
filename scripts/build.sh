#!/usr/bin/env bash
# Configures and builds mechanist (Release) into ${BUILD_DIR:-build}; extra CMake options in
# ${MECHANIST_CMAKE_ARGS}.
set -euo pipefail
cd "$(dirname "$0")/.."
build_dir=${BUILD_DIR:-build}
# shellcheck disable=SC2086
cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release ${MECHANIST_CMAKE_ARGS:-}
cmake --build "$build_dir" -j "$(nproc)"
