#!/usr/bin/env bash
# Builds the libFuzzer harnesses (clang, AddressSanitizer, UndefinedBehaviorSanitizer, libFuzzer's
# coverage in every object) into ${BUILD_DIR:-build-fuzz} and runs each for SECONDS (default
# 600; STEP import three times as long) on seed corpora of the examples, tests/data/bad and
# ../shared/data. Crashes, hangs and sanitizer reports go to BUILD_DIR/fuzz/artifacts/<fuzzer>/;
# the run goes on after each (libFuzzer's fork mode), and a summary line per fuzzer ends the
# run. Exit code 1 when any fuzzer left an artifact.
#   scripts/fuzz.sh [SECONDS] [FUZZER...]   e.g. scripts/fuzz.sh 60 stl_reader_fuzzer
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
case $seconds in
  '' | *[!0-9]* | 0) echo "fuzz.sh: expected SECONDS, a positive whole number, found '$seconds'" >&2; exit 2 ;;
esac
shift || true
all=(assembly_file_fuzzer stl_reader_fuzzer obj_reader_fuzzer ply_reader_fuzzer
     off_reader_fuzzer ccd_query_fuzzer analysis_fuzzer step_import_fuzzer part21_records_fuzzer)
if [ $# -gt 0 ]; then fuzzers=("$@"); else fuzzers=("${all[@]}"); fi

scripts/install-deps.sh
build_dir=${BUILD_DIR:-build-fuzz}
CC=clang CXX=clang++ cmake -S . -B "$build_dir" -DCMAKE_BUILD_TYPE=Release -DMECHANIST_FUZZ=ON \
  -DMECHANIST_FUZZ_COVERAGE=ON -DMECHANIST_BUILD_BENCH=OFF > /dev/null
cmake --build "$build_dir" -j "$(nproc)" --target "${fuzzers[@]}"

shared=../shared/data
out=$build_dir/fuzz
# Seeds: every file of the given globs, copied under a name made of its path (the examples'
# files share names; the fuzzer never writes into its inputs).
seed() {
  local name=$1
  shift
  mkdir -p "$out/seeds/$name"
  for f in "$@"; do
    if [ -f "$f" ]; then cp "$f" "$out/seeds/$name/$(echo "$f" | tr / _)"; fi
  done
}
seed assembly_file_fuzzer examples/*/assembly.json tests/data/bad/*.json
seed stl_reader_fuzzer fuzz/seeds/*.stl tests/data/bad/*.stl "$shared"/gears/*/*.stl
seed obj_reader_fuzzer examples/*/*.obj tests/data/bad/*.obj "$shared"/fcl/*.obj
seed ply_reader_fuzzer fuzz/seeds/*.ply tests/data/bad/*.ply
seed off_reader_fuzzer fuzz/seeds/*.off tests/data/bad/*.off
seed analysis_fuzzer fuzz/seeds/*.stl "$shared"/gears/spur_singles/*.stl
seed step_import_fuzzer tests/data/bad/*.step "$shared"/step/*.stp \
  "$shared"/real/revolute_pin_solidedge_chrono/*.stp "$shared"/real/hinge_clamshell_build123d/*.step
seed part21_records_fuzzer tests/data/bad/*.step "$shared"/step/*.stp "$shared"/real/*/*.stp \
  "$shared"/real/*/*.step "$shared"/real/*/*.STEP
# A CCD seed is a query file behind one byte that chooses its kind (even: vertex-face).
seed ccd_query_fuzzer fuzz/seeds/*.ccd
for f in "$shared"/ccd/*/*/*.csv; do
  [ -f "$f" ] || continue
  kind=1
  case $f in */vertex-face/*) kind=0 ;; esac
  { printf '%s' "$kind"; cat "$f"; } > "$out/seeds/ccd_query_fuzzer/$(echo "$f" | tr / _)"
done

# Open CASCADE and VTK keep some memory to the end of the process; leaks are not checked.
export ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=1
export UBSAN_OPTIONS=print_stacktrace=1
status=0
summary=()
for name in "${fuzzers[@]}"; do
  time=$seconds
  timeout=30
  max_len=65536
  if [ "$name" = step_import_fuzzer ]; then time=$((3 * seconds)); timeout=120; max_len=300000; fi
  mkdir -p "$out/corpus/$name" "$out/artifacts/$name" "$out/logs" "$out/bin"
  # Run from a copy: fork mode starts the binary anew for each job, and the build folder may be
  # rebuilt meanwhile.
  cp "$build_dir/fuzz/$name" "$out/bin/$name"
  echo "fuzz: $name for $time s"
  "$out/bin/$name" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
    -max_total_time="$time" -timeout="$timeout" -rss_limit_mb=4096 -max_len="$max_len" \
    -artifact_prefix="$out/artifacts/$name/" "$out/corpus/$name" "$out/seeds/$name" \
    > "$out/logs/$name.log" 2>&1 || true
  # Fork mode's last status line: "#runs: cov: ... exec/s N oom/timeout/crash: a/b/c time: Ts".
  last=$(grep -E '^#[0-9]+: cov:' "$out/logs/$name.log" | tail -1 || true)
  found=$(find "$out/artifacts/$name" -type f | wc -l)
  summary+=("$name: ${last:-no status line (see $out/logs/$name.log)}; artifacts so far: $found")
  if [ "$found" -gt 0 ]; then status=1; fi
done
printf '%s\n' "${summary[@]}"
exit $status
