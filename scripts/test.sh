#!/usr/bin/env bash
# Set up, build, and run every test: the release build's suite; its install, with examples/ built
# and run against the installed package alone (docs/point-api.md); the same suite built by clang under
# AddressSanitizer and UndefinedBehaviorSanitizer (the fuzz preset); every fuzz target for
# UVTK_FUZZ_SECONDS (default 60) each; the Python module's tests (pytest) against its install. Written
# glTF files are checked by the Khronos glTF-Validator (npm), which setup.sh --validator installs.
# docs/robustness.md says what each part checks.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
scripts/setup.sh --validator  # the glTF-Validator the tests of written glTF files run
ctest --test-dir build --output-on-failure -j "$(nproc)"

# The installed API (docs/point-api.md): install the release build into build/install, then build and
# run examples/ against that prefix alone, as a user would.
rm -rf build/install build/examples
cmake --install build --prefix build/install >&2
cmake -S examples -B build/examples -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$PWD/build/install" \
  -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF >&2
uvtk_dir=$(sed -n 's/^uvtk_DIR:PATH=//p' build/examples/CMakeCache.txt)
case "$uvtk_dir" in
  "$PWD/build/install/"*) ;;
  *) echo "test: examples/ found uvtk in '$uvtk_dir', not in build/install" >&2; exit 1 ;;
esac
cmake --build build/examples >&2
ctest --test-dir build/examples --output-on-failure

# The same program built with pkg-config alone (docs/library.md), and the Python module as installed
# (docs/python.md): its tests compare it with the installed program.
c++ -O1 examples/map_verdict/map_verdict.cpp $(PKG_CONFIG_PATH="$PWD/build/install/lib/pkgconfig" pkg-config --cflags --libs uvtk) \
  -o build/examples/map_verdict_pkgconfig
verdict=$(build/examples/map_verdict_pkgconfig examples/map_verdict/sphere.off || true)  # exit 1: a warning
case "$verdict" in
  *"80 faces, verdict warn"*) ;;
  *) echo "test: map_verdict built with pkg-config printed '$verdict'" >&2; exit 1 ;;
esac
site=$(ls -d build/install/lib/python3*/site-packages)
ls "$site"/uvtk*.so > /dev/null  # the module must have been built and installed
PYTHONPATH="$PWD/$site" UVTK_BIN="$PWD/build/install/bin/uvtk" /usr/bin/python3 -m pytest -q -p no:cacheprovider tests/python

scripts/setup.sh --fuzz
# Leaks are errors (but those scripts/lsan.supp lists); any sanitizer report fails the test that made it.
ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)"
scripts/fuzz.sh "${UVTK_FUZZ_SECONDS:-60}" build-fuzz
