#!/usr/bin/env bash
# Runs every libFuzzer target for SECONDS (default 60) each, two at a time, from the seed corpus in
# fuzz/corpus/ plus what earlier runs found (kept in BUILD/fuzz-corpus/, the seeds are never
# written). Fails on any crash, leak, input slower than 1 s or allocation above 2 GB, and then names
# the input that did it (BUILD/fuzz-artifacts/). Prints each target's executions and corpus size.
# Usage: scripts/fuzz.sh [SECONDS] [BUILD-DIR]   (the fuzz preset's build: build-fuzz)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=${2:-build-fuzz}
targets=(obj off ply stl gltf scene image fit scene_paths)

mkdir -p "$build/fuzz-artifacts" "$build/fuzz-logs"
run() {
  local target=$1 corpus=$build/fuzz-corpus/$1
  mkdir -p "$corpus"
  local dict=()
  [ -f "fuzz/$target.dict" ] && dict=(-dict="fuzz/$target.dict")
  ASAN_OPTIONS=detect_leaks=1:intercept_tls_get_addr=0 LSAN_OPTIONS=suppressions=scripts/lsan.supp UBSAN_OPTIONS=print_stacktrace=1 \
    "$build/fuzz/fuzz_$target" -max_total_time="$seconds" -timeout=1 -rss_limit_mb=2048 -malloc_limit_mb=2048 \
    -max_len=65536 -print_final_stats=1 "${dict[@]}" -artifact_prefix="$build/fuzz-artifacts/$target-" \
    "$corpus" "fuzz/corpus/$target" > "$build/fuzz-logs/$target.log" 2>&1
}

pids=()
for target in "${targets[@]}"; do
  run "$target" &
  pids+=($!)
  # Two at a time: one per core.
  if [ ${#pids[@]} -eq 2 ]; then wait "${pids[0]}" || true; pids=("${pids[1]}"); fi
done
wait || true

failed=0
printf '%-6s %10s %12s %8s  %s\n' target seconds executions corpus result
for target in "${targets[@]}"; do
  log=$build/fuzz-logs/$target.log
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus=$(find "$build/fuzz-corpus/$target" -type f | wc -l)
  if grep -q "^stat::number_of_executed_units" "$log" && ! grep -qE "ERROR: (libFuzzer|AddressSanitizer|LeakSanitizer)|runtime error:|SUMMARY: " "$log"; then
    result=ok
  else
    result="FAILED (see $log)"
    failed=1
  fi
  printf '%-6s %10s %12s %8s  %s\n' "$target" "$seconds" "${executions:-?}" "$corpus" "$result"
done
if [ $failed -ne 0 ]; then
  for target in "${targets[@]}"; do
    log=$build/fuzz-logs/$target.log
    grep -qE "ERROR: |runtime error:|SUMMARY: " "$log" && { echo "---- $target"; grep -E -A30 "ERROR: |runtime error:" "$log" | head -60; }
  done
  ls -l "$build/fuzz-artifacts" >&2
  exit 1
fi
