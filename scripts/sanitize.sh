#!/usr/bin/env bash
# Builds arealight and its tests with gcc's AddressSanitizer and UndefinedBehaviorSanitizer
# into build-asan/ and runs them through ctest: any memory error, leak or undefined
# behaviour in our code fails the run. Leaks inside the Vulkan driver (lavapipe and the
# LLVM it JITs with) are not ours and are suppressed by scripts/lsan-driver.supp, which
# names only those libraries.
#   SANITIZE_CTEST_ARGS="-R io" scripts/sanitize.sh    other tests (" " for all of them)
#   SANITIZE_MIRROR=1 scripts/sanitize.sh              the CPU mirror instrumented too
set -euo pipefail
cd "$(dirname "$0")/.."
# vptr (UBSan's dynamic-type check) is off: Debian's glslang is built without RTTI, and the
# check needs the typeinfo of every polymorphic class our code uses (glslang::TShader).
flags="-fsanitize=address,undefined -fno-sanitize=vptr -fno-omit-frame-pointer"
# gcc 12 warns maybe-uninitialized inside libstdc++'s <regex> under ASan (false positives).
flags+=" -fno-sanitize-recover=all -Wno-maybe-uninitialized"
# -O0 -g1 (g1: functions and lines in ASan's reports, no locals), the numeric libraries (the
# oracle, the LTC fitter, the renderer: AREALIGHT_NUMERIC_FLAGS) at -O1: on 2 cores this
# tree built in 230 s against 306 s all at -O1, and its tests took 35 s longer.
# The CPU mirror (every variant's templates as C++, 32 MB) is the Release tree's
# (AREALIGHT_PREBUILT_MIRROR, built by scripts/build.sh, brought up to date here): compiled
# under the sanitizers it was most of this script's build (4 shards, 30 s each at -O0, 111 s
# at -O1); linked uninstrumented it costs the tests little at any level (scripts/test.sh
# builds it at -O0: 28 CPU-backend tests took 60.6 s against 57.5 s at -O3). Its generated
# code is the templates' (the same text as the shaders, checked by glslang and spirv-val);
# SANITIZE_MIRROR=1 compiles it under the sanitizers too, at -O0.
# Catch2's runner, uninstrumented in either tree (tests/CMakeLists.txt), is the Release tree's
# too.
prebuilt=(arealight_test_main)
mirror_args=(-DAREALIGHT_PREBUILT_TEST_MAIN="$PWD/build/tests/libarealight_test_main.a")
if [ "${SANITIZE_MIRROR:-0}" = 1 ]; then
  mirror_args+=(-DAREALIGHT_PREBUILT_MIRROR= -DAREALIGHT_MIRROR_FLAGS=-O0)
else
  prebuilt+=(arealight_mirror)
  mirror_args+=(-DAREALIGHT_PREBUILT_MIRROR="$PWD/build/generator/libarealight_mirror.a")
fi
bash scripts/build.sh "${prebuilt[@]}" >/dev/null
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=None -DCMAKE_CXX_FLAGS="-O0 -g1 $flags" \
  -DAREALIGHT_NUMERIC_FLAGS=-O1 \
  -DCMAKE_EXE_LINKER_FLAGS="$flags" "${mirror_args[@]}" >/dev/null
t0=$SECONDS
cmake --build build-asan -j"$(nproc)" --target arealight_test_programs
echo "sanitize: build took $((SECONDS - t0)) s" >&2

# Allocation stacks of 8 frames and a 64 MB quarantine (30 and 256 by default): glslang and
# lavapipe's LLVM allocate millions of small blocks through ASan's allocator, and one
# lavapipe run of a peak-function kernel took 7.0 s with the defaults, 4.8 s with 2 frames and
# 16 MB, 2.3 s without ASan. 8 frames still name our caller in every report.
export ASAN_OPTIONS="detect_leaks=1:strict_init_order=1:check_initialization_order=1"
ASAN_OPTIONS+=":malloc_context_size=8:quarantine_size_mb=64"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan-driver.supp:print_suppressions=0"
# Keep lavapipe loaded for the whole process. The Vulkan loader dlcloses the driver at
# vkDestroyInstance; a buffer the driver still holds in a global (128 bytes under Debian's
# mesa-vulkan-drivers 22.3.6-1+deb12u2) then looks unreferenced to LeakSanitizer, from a
# module it can no longer name, so no suppression can match it. Preloaded, the driver stays
# mapped and the buffer reachable. The driver then precedes ASan's runtime in the library
# list, which ASan accepts with verify_asan_link_order=0 (its own init runs first anyway,
# from the executable's preinit_array).
lvp_icd=$(ls /usr/share/vulkan/icd.d/lvp_icd*.json 2>/dev/null | head -n1 || true)
if [ -n "$lvp_icd" ]; then
  lvp_lib=$(sed -n 's/.*"library_path": *"\([^"]*\)".*/\1/p' "$lvp_icd")
  if [ -n "$lvp_lib" ] && [ -e "$lvp_lib" ]; then
    export LD_PRELOAD="$lvp_lib${LD_PRELOAD:+:$LD_PRELOAD}"
    ASAN_OPTIONS+=":verify_asan_link_order=0"
  fi
fi
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
cd build-asan
# Not under the sanitizers by default: the tests scripts/plain_only_tests.txt lists (why and
# how long each takes is there); scripts/test.sh runs them in the Release tree.
sanitize_skip=$(grep -v '^#' ../scripts/plain_only_tests.txt | grep -v '^$' | paste -sd'|')
# shellcheck disable=SC2086  # the arguments are meant to split
ctest --output-on-failure -j"$(nproc)" ${SANITIZE_CTEST_ARGS:--E "$sanitize_skip"}
