#!/usr/bin/env bash
# Configures and builds arealight into build/ (Release): every target, or only the ones
# named (scripts/main.sh builds the arealight executable alone, not the tests).
#   bash scripts/build.sh [TARGET...]
#   MIRROR_FLAGS=-O0 bash scripts/build.sh arealight   # the CPU mirror unoptimised (main.sh)
#   BUILD_TESTS=OFF bash scripts/build.sh arealight    # no test suite: Catch2 not needed (main.sh)
#   TEST_FLAGS=-O0 bash scripts/build.sh               # the suite's own files unoptimised (test.sh)
#   BUILD_TYPE=None bash scripts/build.sh arealight    # no optimisation at all (main.sh)
#   RELEASE_FLAGS="-O1 -DNDEBUG" NUMERIC_FLAGS=-O2 bash scripts/build.sh   # test.sh's levels
# BUILD_TYPE (Release by default), RELEASE_FLAGS (CMake's Release options, -O3 -DNDEBUG by
# default), NUMERIC_FLAGS (AREALIGHT_NUMERIC_FLAGS: the oracle, fitter and renderer, after
# the tree's own), MIRROR_FLAGS, BUILD_TESTS and TEST_FLAGS are passed at every configure, so
# a build without them is the default again.
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE="${BUILD_TYPE:-Release}" -DAREALIGHT_MIRROR_FLAGS="${MIRROR_FLAGS:-}" \
  -DCMAKE_CXX_FLAGS_RELEASE="${RELEASE_FLAGS:--O3 -DNDEBUG}" -DAREALIGHT_NUMERIC_FLAGS="${NUMERIC_FLAGS:-}" \
  -DAREALIGHT_BUILD_TESTS="${BUILD_TESTS:-ON}" -DAREALIGHT_TEST_FLAGS="${TEST_FLAGS:-}" >/dev/null
targets=()
for t in "$@"; do targets+=(--target "$t"); done
cmake --build build -j"$(nproc)" "${targets[@]}"
