#!/usr/bin/env bash
# Runs the tet-kernel benchmarks on the demo fish (and blub when ../shared/meshes exists) and
# prints the docs/RESULTS.md table. Usage: bench/run_tet_bench.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d)
args=("fish=$out/fish.json")
# Only the tet kernels (the binary also holds the photon benchmarks); 5 repetitions, of which
# tet_report.py keeps the best, against the load of other jobs on a shared machine.
only=(--benchmark_filter='BM_(TetSteps|RayWalkFull|EmbreeEntryExit|Locate|Parity)' --benchmark_repetitions=5)
"$build/tetglow_bench" "${only[@]}" --benchmark_min_time=0.3 --benchmark_out="$out/fish.json" --benchmark_out_format=json >/dev/null
if [ -f ../shared/meshes/blub.obj ]; then
  "$build/tetglow_bench" "${only[@]}" --benchmark_min_time=0.3 --benchmark_out="$out/blub.json" --benchmark_out_format=json \
    ../shared/meshes/blub.obj >/dev/null
  args+=("blub=$out/blub.json")
fi
python3 bench/tet_report.py "${args[@]}"
