#!/usr/bin/env bash
# Sets up the machine, builds, and runs every test through ctest; then the unit tests again
# under ASan/UBSan (scripts/sanitize.sh) and each reader's fuzz target for 20 s
# (scripts/fuzz.sh; FUZZ_SECONDS=60 or more for a deeper run: CI's 30 minutes are mostly
# spent in the two builds).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
bash scripts/sanitize.sh
FUZZ_SECONDS="${FUZZ_SECONDS:-20}" bash scripts/fuzz.sh
