#!/usr/bin/env bash
# Set up, build, and run every test: the release build's suite; its install, with examples/ built
# and run against the installed package alone (docs/point-api.md); the same suite built by clang under
# AddressSanitizer and UndefinedBehaviorSanitizer (the fuzz preset); every fuzz target for
# UVTK_FUZZ_SECONDS (default 60) each. docs/robustness.md says what each part checks.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
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

scripts/setup.sh --fuzz
# Leaks are errors (but those scripts/lsan.supp lists); any sanitizer report fails the test that made it.
ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)"
scripts/fuzz.sh "${UVTK_FUZZ_SECONDS:-60}" build-fuzz
