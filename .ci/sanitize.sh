#!/usr/bin/env bash
# CI beside the Release build: the whole test suite built with clang under AddressSanitizer +
# UndefinedBehaviorSanitizer (-O1 -g; the first report ends the process with an error), then every
# fuzz target for a bounded time (fuzz/run.sh) from the same build. Usage: .ci/sanitize.sh [SECONDS_PER_TARGET]
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-10}
./setup.sh sanitizers  # clang and its sanitizer and libFuzzer runtimes, where missing

build=build-sanitize
jobs=$(nproc)
start=$SECONDS
# CI builds this from a clean clone each time: ccache, with paths taken relative to the clone,
# compiles only what changed since the last run, wherever the clone lies.
export CCACHE_BASEDIR="$PWD" CCACHE_NOHASHDIR=true
CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" \
  -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DTETGLOW_FUZZ=ON >/dev/null
cmake --build "$build" -j "$jobs"
echo "sanitize: built in $((SECONDS - start)) s"

# Leak detection stays on with no suppressions: TBB, Embree, OpenEXR and TetGen (in its child
# process) report no leak in the whole suite, so none is hidden.
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
# Sanitized code runs several times slower: tests that wait for a server scale their bounds.
export TETGLOW_TEST_TIME_SCALE=6
start=$SECONDS
# The tests that drive Blender (label blender: the add-on's, GltfBlender) compare Blender's own renders
# with tetglow's; the tetglow paths they drive are the suite's own, so the sanitized run leaves
# them to the Release one.
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE blender
echo "sanitize: test suite passed in $((SECONDS - start)) s"

start=$SECONDS
fuzz/run.sh "$seconds" "$build"
echo "sanitize: fuzzing passed in $((SECONDS - start)) s"
