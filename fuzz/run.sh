#!/usr/bin/env bash
# Runs every fuzz target for SECONDS_PER_TARGET (default 60) from its starting inputs in fuzz/corpus/<target>/,
# building them first (clang, -DTETGLOW_FUZZ=ON) in BUILD_DIR (default build-fuzz). New inputs go
# to BUILD_DIR/fuzz/<target>/corpus, never into the committed inputs; a finding (crash, sanitizer
# report, escaped exception, input slower than 10 s, over 2 GiB) is saved as
# BUILD_DIR/fuzz/<target>/finding-* and makes the script fail after the other targets have run.
# Reproduce one with: BUILD_DIR/fuzz/fuzz_<target> FILE
#   fuzz/run.sh [SECONDS_PER_TARGET] [BUILD_DIR]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
build=${2:-build-fuzz}
case "$seconds" in '' | *[!0-9]*) echo "usage: $0 [SECONDS_PER_TARGET] [BUILD_DIR]" >&2; exit 2 ;; esac

if [ ! -f "$build/CMakeCache.txt" ]; then
  ./setup.sh sanitizers
  CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
    -DTETGLOW_FUZZ=ON -DTETGLOW_BUILD_TESTS=OFF -DTETGLOW_BUILD_BENCH=OFF >/dev/null
fi
cmake --build "$build" -j "$(nproc)" >/dev/null

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
failed=()
for inputs in fuzz/corpus/*/; do
  target=$(basename "$inputs")
  work=$build/fuzz/$target
  mkdir -p "$work/corpus"
  log=$work/log.txt
  if "$build/fuzz/fuzz_$target" "$work/corpus" "$inputs" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
       -max_len=65536 -print_final_stats=1 -artifact_prefix="$work/finding-" >"$log" 2>&1; then
    echo "fuzz: $target: $(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$') runs," \
         "$(ls "$work/corpus" | wc -l) inputs in its corpus, no finding"
  else
    failed+=("$target")
    echo "fuzz: $target: FINDING (log: $log)" >&2
    grep -E "ERROR|SUMMARY|runtime error|Test unit written" "$log" | head -5 >&2 || true
  fi
done
if ((${#failed[@]})); then
  echo "fuzz: findings in ${failed[*]}" >&2
  exit 1
fi
