#!/usr/bin/env bash
# Sets up the machine, builds, and runs every test through ctest; then the unit tests again
# under ASan/UBSan (scripts/sanitize.sh) and each reader's fuzz target for 60 s
# (scripts/fuzz.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
bash scripts/build.sh
(cd build && ctest --output-on-failure -j"$(nproc)")
bash scripts/sanitize.sh
bash scripts/fuzz.sh
