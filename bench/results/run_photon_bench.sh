#!/usr/bin/env bash
# The fish with photon mapping against a volpath reference rendered to convergence, and volpath
# given the same time. Prints the table; --docs also rewrites the photon-fish section of
# docs/RESULTS.md. Usage: bench/results/run_photon_bench.sh [--docs] [build-dir] [reference.exr]
# Without a reference it renders one first (scenes/fish.json, volpath, 4096 spp: about 7 minutes
# on 2 idle cores) and keeps it as ref/fish-volpath-4096.exr for the next run.
set -euo pipefail
docs=0
if [ "${1:-}" = --docs ]; then docs=1; shift; fi
cd "$(dirname "$0")/../.."
build=${1:-build}
ref=${2:-ref/fish-volpath-4096.exr}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
"$build/tetglow" tetrahedralize scenes/meshes/fish.obj >/dev/null  # warm the tet cache
if [[ ! -f $ref ]]; then
  mkdir -p "$(dirname "$ref")"
  "$build/tetglow" render scenes/fish.json --integrator volpath --spp 4096 --seed 777 -o "$ref" >/dev/null
fi

field() {  # field NAME JSON: a number from `tetglow diff --json`
  python3 -c "import json,sys; print('%.4g' % json.load(sys.stdin)['$1'])" <<<"$2"
}
# row LABEL ARGS...: renders the fish with ARGS, prints wall time, relative MSE, RMSE.
row() {
  local label=$1; shift
  local start end diff
  start=$(date +%s%N)
  "$build/tetglow" render scenes/fish.json -o "$out/test.exr" "$@" >/dev/null 2>&1
  end=$(date +%s%N)
  diff=$("$build/tetglow" diff "$out/test.exr" "$ref" --json)
  wall=$(( (end - start) / 1000000 ))
  echo "| $label | \`$*\` | $(awk "BEGIN{printf \"%.1f\", $wall/1000}") | $(field rel_mse "$diff") | $(field rmse "$diff") |"
}

table() {
  echo "| method | arguments to \`tetglow render scenes/fish.json\` | wall (s) | relative MSE | RMSE |"
  echo "|---|---|---|---|---|"
  row "photon (the demo, as committed)"
  demo_wall=$wall
  row "volpath, same time as the demo" --integrator volpath --time "$(awk "BEGIN{print $demo_wall/1000}")"
  row "volpath, 64 spp" --integrator volpath --spp 64
  row "photon, beam, no boundary correction" --boundary-correction off
  row "photon, knn-march (the parity baseline's estimate), 4 passes" --estimate knn-march --passes 4
  row "photon, beam, 16 passes" --passes 16
}
table | tee "$out/table.md"
if [ $docs = 1 ]; then
  python3 bench/benchlib.py section photon-fish "bench/results/run_photon_bench.sh --docs" < "$out/table.md"
fi
