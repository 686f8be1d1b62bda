#!/usr/bin/env bash
# Rewrites the pinned example reports in tests/cli/golden/ from the built mechanist
# (build/cli/mechanist, or $MECHANIST). Only for an intended change of behaviour: the test
# tests/cli/example_reports_test.cpp compares every run against these files byte for byte.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mechanist="${MECHANIST:-$root/build/cli/mechanist}"
for dir in "$root"/examples/*/; do
  name="$(basename "$dir")"
  out="$root/tests/cli/golden/$name"
  rm -rf "$out"
  mkdir -p "$out"
  (
    cd "$dir"
    for command in validate info analyze check interference assemble sweep; do
      extra=()
      case "$command" in
        analyze) extra=(--json "$out/analyze.json" --dot "$out/analyze.dot") ;;
        interference | assemble | sweep) extra=(--json "$out/$command.json") ;;
      esac
      set +e
      "$mechanist" "$command" assembly.json "${extra[@]}" > "$out/$command.txt" 2>&1
      echo "exit $?" >> "$out/$command.txt"
      set -e
    done
  )
done
echo "golden reports written to tests/cli/golden/"
