#!/usr/bin/env bash
# Quick start, step 2: install dependencies, build from scratch, run the whole test suite.
#   scripts/test.sh              the Release build (g++)
#   scripts/test.sh --sanitize   the same suite built by clang with AddressSanitizer and
#                                UndefinedBehaviorSanitizer, with the fuzzers of fuzz/ replaying
#                                their seeds and the bad-input corpus (CI runs both)
set -euo pipefail
cd "$(dirname "$0")/.."
sanitize=false
if [ "${1:-}" = --sanitize ]; then sanitize=true; fi
scripts/install-deps.sh
if $sanitize; then
  export BUILD_DIR=${BUILD_DIR:-build-sanitize}
else
  export BUILD_DIR=${BUILD_DIR:-build-test}
fi
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

excluded=()
if $sanitize; then
  export CC=clang CXX=clang++
  # The fuzzers are built to replay their seeds; without libFuzzer's coverage, which only
  # fuzzing needs (scripts/fuzz.sh builds with it), the sanitized tests take 0.6 of the time.
  MECHANIST_CMAKE_ARGS+=" -DMECHANIST_FUZZ=ON -DMECHANIST_FUZZ_COVERAGE=OFF"
  MECHANIST_CMAKE_ARGS+=" -DMECHANIST_BUILD_BENCH=OFF"
  # Any report ends the test that made it. Open CASCADE and VTK keep some memory to the end of
  # the process, so leaks are not checked.
  export ASAN_OPTIONS=detect_leaks=0:abort_on_error=1
  export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
  # The installed package's consumer would need the sanitizers' runtime too. The end-to-end
  # runs of whole examples (viewer pages in the browser, simulator exports, animations, the
  # pinned example reports, the examples' sweeps) mostly take 30 to 570 s each under the
  # sanitizers, three quarters of the suite's time; they run the code the unit tests cover,
  # and they run in the Release build (README, "Robustness").
  excluded=(-E '^(install\.consumer|viz\.(gltf_validator|vtp_series_vtk_reader)|ViewerPage\..*|Examples/Simulators\..*|Examples/ExampleReports\..*|Cli\.(View|Animate).*|AssemblyExamples\.EveryExample.*)')
fi

scripts/build.sh
# Rendering needs an X display: a virtual one, kept from resetting between test processes.
xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" \
  ctest --test-dir "$BUILD_DIR" --output-on-failure -j "$(nproc)" "${excluded[@]}"
