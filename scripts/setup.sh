#!/usr/bin/env bash
# Installs the Debian packages uvtk needs (only those missing), then configures and builds.
# Usage: scripts/setup.sh [build-dir]   the release build (default: build)
#        scripts/setup.sh --fuzz        the fuzz preset (clang, ASan + UBSan + libFuzzer): build-fuzz
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake ninja-build g++ pkg-config
          libeigen3-dev libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev
          libopenimageio-dev openimageio-tools
          libssl-dev zlib1g-dev libsleef-dev libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
          libosmesa6-dev   # Mesa's software OpenGL: the reference the texgen tests compare with
          python3-dev pybind11-dev python3-numpy python3-pytest)  # the Python module (docs/python.md) and its tests
preset=""
build_dir=${1:-build}
if [ "${1:-}" = "--fuzz" ]; then
  preset=fuzz
  build_dir=build-fuzz
  # clang with its sanitizer and libFuzzer runtimes; llvm-symbolizer makes the reports readable.
  packages+=(clang libclang-rt-14-dev llvm)
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  [ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
  "${sudo_cmd[@]}" apt-get update -qq
  DEBIAN_FRONTEND=noninteractive "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >&2
fi

if [ ! -f "$build_dir/build.ninja" ]; then
  if [ -n "$preset" ]; then
    cmake --preset "$preset" >&2
  else
    cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
  fi
fi
cmake --build "$build_dir" -j "$(nproc)" >&2
