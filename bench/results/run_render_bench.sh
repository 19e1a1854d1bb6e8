#!/usr/bin/env bash
# Render throughput on the demo fish: volpath samples per second on 1 and 2 threads (the
# ratio is the parallel speed-up), the demo render itself, and the published slab. Prints the
# tables; --docs also rewrites the render-throughput and slab sections of docs/RESULTS.md.
# Usage: bench/results/run_render_bench.sh [--docs] [build-dir]
set -euo pipefail
docs=0
if [ "${1:-}" = --docs ]; then docs=1; shift; fi
cd "$(dirname "$0")/../.."
build=${1:-build}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
# Warm the tet cache so that every row measures rendering only.
"$build/tetglow" tetrahedralize scenes/meshes/fish.obj >/dev/null

rate() {  # samples/s printed by `tetglow render`
  sed -n 's/.*(\([0-9]*\) samples\/s).*/\1/p' <<<"$1"
}
throughput() {
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
  echo "| demo: scenes/fish.json as committed, whole command $(( (end - start) / 1000000 )) ms wall | all | $(sed -n 's/.*rendering \([0-9.]*\) s.*/\1/p' <<<"$log") | $(rate "$log") |"
}
slab() {  # the published slab as a table against van de Hulst's and MCML's values
  SLAB=$("$build/tetglow" validate slab --tau 2 --albedo 0.9 --g 0.75 --photons 10000000 --json) python3 - <<'PY'
import json, os
r = json.loads(os.environ["SLAB"])
cell = lambda x: f"{x['mean']:.5f} ± {x['std_error']:.5f}"
off = lambda x, v: f"{(x['mean'] - v) / x['std_error']:+.1f} standard errors"
print("| quantity | tetglow | published (van de Hulst, MCML) | difference |")
print("|---|---|---|---|")
print(f"| diffuse reflectance Rd | {cell(r['Rd'])} | 0.09739 | {off(r['Rd'], 0.09739)} |")
print(f"| total transmittance Tt | {cell(r['Tt'])} | 0.66096 | {off(r['Tt'], 0.66096)} |")
print(f"| absorbed | {cell(r['absorbed'])} | (1 - Rd - Tt = {1 - 0.09739 - 0.66096:.5f}) | |")
print(f"\n{r['photons']} photons through {r['tets']} tets in {r['seconds']:.1f} s; "
      f"lost through the sides of the box: {r['lost_sideways']['mean']:.5f}.")
PY
}
throughput | tee "$out/throughput.md"
echo
slab | tee "$out/slab.md"
if [ $docs = 1 ]; then
  python3 bench/benchlib.py section render-throughput "bench/results/run_render_bench.sh --docs" < "$out/throughput.md"
  python3 bench/benchlib.py section slab "bench/results/run_render_bench.sh --docs" < "$out/slab.md"
fi
