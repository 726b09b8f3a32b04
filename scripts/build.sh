#!/usr/bin/env bash
# Configures and builds arealight into build/ (Release): every target, or only the ones
# named (scripts/main.sh builds the arealight executable alone, not the tests).
#   bash scripts/build.sh [TARGET...]
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
