#!/usr/bin/env bash
# Installs the Debian packages arealight needs.
#   bash scripts/setup.sh        everything: build, tests, sanitizers, fuzzers (scripts/test.sh)
#   bash scripts/setup.sh main   what building arealight and running it need (scripts/main.sh):
#                                not Catch2, clang and its sanitizer runtime, the consumer test's
#                                Ninja or vulkan-tools, of which clang alone brings about 250 MB
#                                of LLVM 14 beside Mesa's LLVM 15
# Idempotent: does nothing when all packages are already present.
set -euo pipefail

PACKAGES=(
  build-essential cmake pkg-config
  # glslang-tools too: Debian's glslang-dev CMake package refers to /usr/bin/glslangValidator
  # and find_package(glslang) fails without it (seen on a debootstrapped bookworm).
  glslang-dev glslang-tools spirv-tools spirv-headers
  libvulkan-dev mesa-vulkan-drivers
  libglm-dev libfmt-dev libcli11-dev nlohmann-json3-dev
  libboost-dev libzstd-dev libcapstone-dev libnlopt-cxx-dev libpng-dev
  python3
)
case "${1:-all}" in
  main) ;;
  all) PACKAGES+=(vulkan-tools catch2 ninja-build clang libclang-rt-14-dev) ;;
  *) echo "usage: bash scripts/setup.sh [main]" >&2; exit 2 ;;
esac

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
