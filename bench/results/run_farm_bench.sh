#!/usr/bin/env bash
# The fish's volpath reference rendered by one process (2 threads) and as PARTS tasks of a Slurm
# job array through the local single-node cluster (tests/slurm/local-cluster.sh; root, and
# Debian's slurmctld, slurmd, slurm-client and munge): wall times, and whether the merged image
# is the single render bit for bit. Prints the table; --docs also rewrites the farm section of
# docs/RESULTS.md. Usage: bench/results/run_farm_bench.sh [--docs] [build-dir] [spp] [parts] [out-dir]
set -euo pipefail
docs=0
if [ "${1:-}" = --docs ]; then docs=1; shift; fi
cd "$(dirname "$0")/../.."
build=${1:-build}
spp=${2:-4096}
parts=${3:-8}
out=${4:-out/farm-bench}
mkdir -p "$out"
cluster=$(mktemp -d)
trap 'tests/slurm/local-cluster.sh stop "$cluster"; rm -rf "$cluster"' EXIT
tests/slurm/local-cluster.sh start "$cluster"
export SLURM_CONF=$cluster/slurm.conf
args=(scenes/fish.json --integrator volpath --spp "$spp" --seed 777)
"$build/tetglow" render "${args[@]}" --tetrahedralize-only 2>/dev/null  # both runs read the tets from the cache

wall() {  # seconds the command took
  local start end
  start=$(date +%s%N)
  "$@" > /dev/null 2>&1
  end=$(date +%s%N)
  echo "$(( (end - start) / 1000000 ))" | sed 's/\(...\)$/.\1/'
}
load() { cut -d' ' -f1-3 /proc/loadavg; }
table() {
  echo "| run | wall (s) | load average before |"
  echo "|---|---|---|"
  l=$(load); echo "| one process, 2 threads: tetglow render ${args[*]} | $(wall "$build/tetglow" render "${args[@]}" -o "$out/single.exr") | $l |"
  l=$(load); echo "| $parts parts, 1 thread each, 2 at a time: tetglow farm ${args[*]} --parts $parts --wait | $(wall "$build/tetglow" farm "${args[@]}" --parts "$parts" -o "$out/farm.exr" --wait) | $l |"
  echo
  if cmp -s "$out/single.exr" "$out/farm.exr"; then echo "merged image: identical to the single render (cmp: the EXR files are byte for byte the same)"
  else echo "merged image: DIFFERS from the single render"; "$build/tetglow" diff "$out/farm.exr" "$out/single.exr"; exit 1; fi
  echo "task rendering times (s): $(grep -h '^time:' "$out"/farm.farm/task-*.log | sed 's/.*rendering \([0-9.]*\) s.*/\1/' | tr '\n' ' ')"
}
table | tee "$out/table.md"
if [ $docs = 1 ]; then
  python3 bench/benchlib.py section farm "bench/results/run_farm_bench.sh --docs ${build} ${spp} ${parts}" < "$out/table.md"
fi
