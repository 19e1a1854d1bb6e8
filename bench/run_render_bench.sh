#!/usr/bin/env bash
# Render throughput on the demo fish: volpath samples per second on 1 and 2 threads (the
# ratio is the parallel speed-up), the demo render itself, and the published slab.
# Prints the docs/RESULTS.md rows. Usage: bench/run_render_bench.sh [build-dir]
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Warm the tet cache so that every row measures rendering only.
"$build/tetglow" tetrahedralize scenes/meshes/fish.obj >/dev/null

rate() {  # samples/s printed by `tetglow render`
  sed -n 's/.*(\([0-9]*\) samples\/s).*/\1/p' <<<"$1"
}
echo "| run | threads | rendering (s) | samples/s |"
echo "|---|---|---|---|"
for threads in 1 2; do
  log=$("$build/tetglow" render scenes/fish.json --integrator volpath --spp 16 --threads "$threads" -o "$out/fish.exr" 2>/dev/null)
  secs=$(sed -n 's/.*rendering \([0-9.]*\) s.*/\1/p' <<<"$log")
  echo "| volpath, fish 400x400, 16 spp | $threads | $secs | $(rate "$log") |"
done
start=$(date +%s%N)
log=$("$build/tetglow" render scenes/fish.json -o "$out/demo.exr" 2>/dev/null)
end=$(date +%s%N)
echo "| demo: scenes/fish.json as committed (photon, 100 passes), wall time of the whole command $(( (end - start) / 1000000 )) ms | all | $(sed -n 's/.*rendering \([0-9.]*\) s.*/\1/p' <<<"$log") | $(rate "$log") |"
echo
echo '```'
"$build/tetglow" validate slab --tau 2 --albedo 0.9 --g 0.75 --photons 10000000
echo '```'
