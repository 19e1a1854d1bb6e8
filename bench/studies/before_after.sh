#!/usr/bin/env bash
# Whether a change made tetglow slower: the kernel benchmarks (tetglow_bench) and whole renders of
# a base build and a new build, alternating in one run. Each figure is the best of its repetitions
# (other jobs on a shared machine only slow a run down); the last column is new / base (above 1:
# the new build is faster). The tet kernels run on blub (../shared/meshes) where it exists, else on
# each tree's own fish; the photon kernels on their fixed synthetic inputs, except the photon
# tracing, which reads each tree's scenes/fish.json (compare it only where that file is the same);
# the renders read this tree's sphere.json and blub.json with both builds.
# Where a build has no tetglow_bench, only the renders are compared.
# Usage: bench/studies/before_after.sh BASE_BUILD NEW_BUILD [REPETITIONS]
set -euo pipefail
cd "$(dirname "$0")/../.."
base=${1:?usage: before_after.sh BASE_BUILD NEW_BUILD [REPETITIONS]}
new=${2:?usage: before_after.sh BASE_BUILD NEW_BUILD [REPETITIONS]}
reps=${3:-3}
kernels=1
for b in "$base" "$new"; do
  [ -x "$b/tetglow" ] || { echo "before_after: $b/tetglow not found" >&2; exit 1; }
  if [ ! -x "$b/tetglow_bench" ]; then
    echo "before_after: $b/tetglow_bench not found (configure with -DTETGLOW_BUILD_BENCH=ON): renders only" >&2
    kernels=0
  fi
done
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
mesh=()
scenes=(sphere)
if [ -f ../shared/meshes/blub.obj ]; then
  mesh=(../shared/meshes/blub.obj)
  scenes+=(blub)
else
  echo "before_after: ../shared/meshes not found: tet kernels on each tree's fish, renders of sphere.json only" >&2
fi
filter='BM_(TetSteps|RayWalkFull|EmbreeEntryExit|LocateWithHint|ParityAlongPath|PhotonKnn|PhotonRadius|PhotonDiscs|TracePhotons)'
declare -A integrator=([volpath]="--integrator volpath --spp 16" [photon]="--integrator photon --passes 4 --photons 50000")
for scene in "${scenes[@]}"; do  # warm both builds' tet caches: the renders time rendering
  for side in base new; do "${!side}/tetglow" render "scenes/$scene.json" --resolution 8x8 --spp 1 -o "$out/warm.exr" >/dev/null 2>&1; done
done
for ((r = 1; r <= reps; ++r)); do
  for side in base new; do
    b=${!side}
    if [ $kernels = 1 ]; then
      "$b/tetglow_bench" --benchmark_filter="$filter" --benchmark_min_time=0.2 \
        --benchmark_out="$out/$side-$r.json" --benchmark_out_format=json "${mesh[@]}" >/dev/null
    fi
    for scene in "${scenes[@]}"; do
      for integ in volpath photon; do
        start=$(date +%s%N)
        # shellcheck disable=SC2086
        "$b/tetglow" render "scenes/$scene.json" ${integrator[$integ]} --resolution 128x128 --threads 2 --seed 1 \
          -o "$out/render.exr" >/dev/null 2>&1
        end=$(date +%s%N)
        echo "$side render:$scene:$integ $(((end - start) / 1000000))" >>"$out/renders.txt"
      done
    done
  done
done
python3 - "$out" "$reps" "$kernels" <<'PY'
import json, sys
out, reps, kernels = sys.argv[1], int(sys.argv[2]), sys.argv[3] == "1"
best = {"base": {}, "new": {}}  # name -> (rate, unit): higher is faster
for side in best:
    for r in range(1, reps + 1 if kernels else 1):
        for b in json.load(open(f"{out}/{side}-{r}.json"))["benchmarks"]:
            if b.get("run_type") == "aggregate":
                continue
            keys = [k for k in ("steps/s", "rays/s", "points/s", "items_per_second") if k in b]
            rate, unit = (b[keys[0]], keys[0]) if keys else (1e9 / b["real_time"], "runs/s")
            name = b.get("run_name", b["name"])
            if rate > best[side].get(name, (0, ""))[0]:
                best[side][name] = (rate, unit)
for line in open(f"{out}/renders.txt"):
    side, name, ms = line.split()
    rate = 1000.0 / float(ms)
    if rate > best[side].get(name, (0, ""))[0]:
        best[side][name] = (rate, "renders/s (whole command, 128x128, 2 threads)")
print("| benchmark | unit | base | new | new / base |")
print("|---|---|---|---|---|")
for name in sorted(set(best["base"]) & set(best["new"])):
    (b, unit), (n, _) = best["base"][name], best["new"][name]
    print(f"| {name} | {unit} | {b:.4g} | {n:.4g} | {n / b:.3f} |")
PY
