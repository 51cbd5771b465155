#!/usr/bin/env bash
# Installs the Debian packages uvtk needs (only those missing), then configures and builds.
# Usage: scripts/setup.sh [build-dir]   the release build (default: build)
#        scripts/setup.sh build --program   only the program and its image plugin (about half the
#                                       compiling: no library for C++ users, Python module or tests)
#        scripts/setup.sh --fuzz        the fuzz preset (clang, ASan + UBSan + libFuzzer): build-fuzz
#        scripts/setup.sh --validator   the Khronos glTF-Validator and the browser test's tools (Debian's
#                                       nodejs, npm and chromium, then the npm packages pinned in
#                                       tests/gltf_validator and tests/browser) in build/gltf-validator
#                                       and build/browser-test; nothing is built
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(cmake ninja-build g++ pkg-config
          libeigen3-dev libopenmesh-dev libcgal-dev libgmp-dev libmpfr-dev
          libopenimageio-dev openimageio-tools
          libssl-dev zlib1g-dev libsleef-dev libcli11-dev nlohmann-json3-dev libgtest-dev libgmock-dev libbenchmark-dev
          libtinygltf-dev  # glTF 2.0 in (io/gltf_reader.cpp)
          libdragonbox-dev # the shortest digits of a double, for the mesh writers (io/shortest_number.cpp)
          libhwy-dev       # Google Highway: portable SIMD for the rasterizer and the mapping kernel
          libassimp-dev    # the peer `uvtk bench` times (aiProcess_GenUVCoords); optional to the build
          libosmesa6-dev   # Mesa's software OpenGL: the reference the texgen tests compare with
          libfreetype-dev fonts-dejavu-core  # the views' type: DejaVu Sans drawn by FreeType (views/type.h)
          python3-dev pybind11-dev python3-numpy python3-pytest  # the Python module (docs/python.md) and its tests
          python3-pip python3-venv  # pip wheel . and the fresh virtual environment the wheel is tested in
          mypy python3-meshio python3-dask python3-distributed)  # the stubs' check, meshio's layout, Dask batches
preset=""
build_dir=${1:-build}
if [ "${1:-}" = "--fuzz" ]; then
  preset=fuzz
  build_dir=build-fuzz
  # clang with its sanitizer and libFuzzer runtimes; llvm-symbolizer makes the reports readable.
  packages+=(clang libclang-rt-14-dev llvm)
fi
if [ "${1:-}" = "--validator" ]; then
  packages=()
  command -v node > /dev/null || packages+=(nodejs)
  command -v npm > /dev/null || packages+=(npm)
  [ -x /usr/bin/chromium ] || packages+=(chromium)  # the browser test's headless browser (tests/browser)
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

if [ "${1:-}" = "--validator" ]; then
  mkdir -p build/gltf-validator
  cp tests/gltf_validator/package.json tests/gltf_validator/package-lock.json tests/gltf_validator/validate.mjs \
    build/gltf-validator/
  (cd build/gltf-validator && npm ci --no-audit --no-fund --loglevel=error) >&2
  # puppeteer-core drives Debian's Chromium; tests/browser/run.sh runs check_pages.mjs from the source tree.
  mkdir -p build/browser-test
  cp tests/browser/package.json tests/browser/package-lock.json build/browser-test/
  (cd build/browser-test && npm ci --no-audit --no-fund --loglevel=error) >&2
  exit 0
fi

if [ ! -f "$build_dir/build.ninja" ]; then
  if [ -n "$preset" ]; then
    cmake --preset "$preset" >&2
  else
    cmake -S . -B "$build_dir" -G Ninja -DCMAKE_BUILD_TYPE=Release >&2
  fi
fi
targets=()
[ "${2:-}" = "--program" ] && targets=(--target uvtk uvtk_image_oiio uvtk_benchmark_runner)
cmake --build "$build_dir" -j "$(nproc)" "${targets[@]}" >&2
