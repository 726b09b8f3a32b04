#!/usr/bin/env bash
# Sets up the machine, builds, and runs the main job: the reference oracle over
# the example cases, with a summary table.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
mkdir -p out
build/arealight reference --cases examples/cases.json --out out/examples.ref.json --table
