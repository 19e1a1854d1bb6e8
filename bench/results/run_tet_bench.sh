#!/usr/bin/env bash
# Runs the tet-kernel benchmarks on the demo fish (and blub when ../shared/meshes exists) and
# prints their tables; --docs also rewrites the tet-kernels section of docs/RESULTS.md.
# Usage: bench/results/run_tet_bench.sh [--quick | --docs] [build-dir]
set -euo pipefail
# --quick (the test suite's TetBenchQuick): the fish only, each kernel once and briefly, to check
# that the benchmarks run, locate every march sample in the right tet and report.
reps=5 minTime=0.3 meshes=1 docs=0
if [ "${1:-}" = --quick ]; then reps=1 minTime=0.01 meshes=0; shift; fi
if [ "${1:-}" = --docs ]; then docs=1; shift; fi
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
args=("fish=$out/fish.json")
# Only the tet kernels (the binary also holds the photon benchmarks); 5 repetitions, of which
# tet_report.py keeps the best, against the load of other jobs on a shared machine.
only=(--benchmark_filter='BM_(TetSteps|RayWalkFull|EmbreeEntryExit|Locate|Parity)' --benchmark_repetitions=$reps
      --benchmark_min_time=$minTime)
"$build/tetglow_bench" "${only[@]}" --benchmark_out="$out/fish.json" --benchmark_out_format=json >/dev/null
if [ $meshes = 1 ] && [ -f ../shared/meshes/blub.obj ]; then
  "$build/tetglow_bench" "${only[@]}" --benchmark_out="$out/blub.json" --benchmark_out_format=json \
    ../shared/meshes/blub.obj >/dev/null
  args+=("blub=$out/blub.json")
fi
python3 bench/results/tet_report.py "${args[@]}" | tee "$out/report.md"
if [ $docs = 1 ]; then
  python3 bench/benchlib.py section tet-kernels "bench/results/run_tet_bench.sh --docs" < "$out/report.md"
fi
