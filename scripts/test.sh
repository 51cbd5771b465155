#!/usr/bin/env bash
# Set up, build, and run every test: the release build's suite; the same suite built by clang under
# AddressSanitizer and UndefinedBehaviorSanitizer (the fuzz preset); every fuzz target for
# UVTK_FUZZ_SECONDS (default 60) each. docs/robustness.md says what each part checks.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup.sh build
ctest --test-dir build --output-on-failure -j "$(nproc)"

scripts/setup.sh --fuzz
# Leaks are errors (but those scripts/lsan.supp lists); any sanitizer report fails the test that made it.
ctest --test-dir build-fuzz --output-on-failure -j "$(nproc)"
scripts/fuzz.sh "${UVTK_FUZZ_SECONDS:-60}" build-fuzz
