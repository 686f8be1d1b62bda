#!/usr/bin/env bash
# Quick start, step 1: install dependencies, build, and run the main job (validate, info,
# analyze, then the interactive viewer) on a bundled example.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
example=${1:-examples/robot_hand_worm/assembly.json}
build/cli/mechanist validate "$example"
build/cli/mechanist info "$example"
build/cli/mechanist analyze "$example"
# The interactive viewer of the example: one HTML file, opened by double-click.
build/cli/mechanist view "$example" --out "$(basename "$(dirname "$example")").html"
