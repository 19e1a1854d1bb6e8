#!/usr/bin/env bash
# `tetglow farm` through a real Slurm (a local single-node cluster, tests/slurm/local-cluster.sh):
# a partition or an output path that would smuggle a command into the scripts is refused before
# anything is written or submitted; an output folder with quotes, '#', spaces and '%' works (bash
# and sbatch's #SBATCH parser each read their lines as meant, Slurm's --output expands no '%');
# 4 parts, submitted with an account, a time limit, memory and an extra sbatch option that every
# job carries, give the image `tetglow render` gives, byte for byte; a turntable's frames split
# the same way; a task that fails fails the merge job with that task's error and leaves no image,
# and so does a failed tet-cache job (whose array then never runs); an array over the cluster's
# MaxArraySize is refused before anything is submitted; --preamble and --setup lines run first
# in every job, as written.
#   tests/slurm/farm_test.sh TETGLOW_BINARY SOURCE_DIR
# Exit 77 (CTest: skipped) with a message where Slurm or munge is not installed, or not as root.
set -euo pipefail
tetglow=${1:?usage: $0 TETGLOW_BINARY SOURCE_DIR}
source_dir=${2:?usage: $0 TETGLOW_BINARY SOURCE_DIR}
for program in munged slurmctld slurmd sbatch squeue scancel sinfo; do
    if ! command -v "$program" >/dev/null; then
        echo "SKIP: $program is not installed (./setup.sh test installs slurmctld, slurmd, slurm-client and munge)"
        exit 77
    fi
done
if [ "$(id -u)" -ne 0 ]; then echo "SKIP: the local Slurm daemons run as root"; exit 77; fi

dir=$(mktemp -d)
cluster=$source_dir/tests/slurm/local-cluster.sh
trap '"$cluster" stop "$dir"; rm -rf "$dir"' EXIT
"$cluster" start "$dir"
export SLURM_CONF=$dir/slurm.conf TETGLOW_CACHE_DIR=$dir/cache
fail() { echo "FAIL: $*" >&2; exit 1; }
scene=$source_dir/scenes/sphere.json
options=(--resolution 24x20 --spp 10 --seed 4 --integrator photon --photons 2000)

"$tetglow" render "$scene" "${options[@]}" -o "$dir/single.exr" > /dev/null 2>&1

echo "== a partition with a newline and a command: refused, nothing written or run"
marker=$dir/pwned
if "$tetglow" farm "$scene" --parts 2 "${options[@]}" --partition "test
touch $marker" -o "$dir/hostile/a.exr" --wait 2> "$dir/hostile.err"; then
    fail "farm accepted a partition with a newline"
fi
cat "$dir/hostile.err"
grep -q -- "--partition: expected names of letters" "$dir/hostile.err" || fail "the refusal does not name --partition"
[ ! -e "$marker" ] || fail "the command in the partition ran"
[ ! -e "$dir/hostile" ] || fail "farm wrote files for a refused partition"

echo "== an output path with a backslash, a quote, a newline and a command: refused, nothing written or run"
if "$tetglow" farm "$scene" --parts 2 "${options[@]}" -o "$dir/hostile/x\\'
touch $marker
/a.exr" --wait 2> "$dir/hostile.err"; then
    fail "farm accepted an output path with a newline"
fi
cat "$dir/hostile.err"
grep -q "holds a control character: refusing to write it into a batch script" "$dir/hostile.err" || fail "the refusal does not say why"
[ ! -e "$marker" ] || fail "the command in the output path ran"
[ ! -e "$dir/hostile" ] || fail "farm wrote files for a refused output path"

echo "== an output folder with quotes, '#', spaces and Slurm's and printf's '%' patterns"
odd="$dir/it's \"a\" #1 100%d %a %20"
"$tetglow" farm "$scene" --parts 2 "${options[@]}" -o "$odd/sphere.exr" --wait
cmp "$odd/sphere.exr" "$dir/single.exr" || fail "the farm's image in the odd folder differs from the single render"
for log in task-0.log task-1.log prepare.log merge.log; do
    [ -s "$odd/sphere.farm/$log" ] || fail "$log is not in $odd/sphere.farm (Slurm expanded the folder's '%')"
done
[ "$(find "$dir" -name 'part-*' | grep -vc "^$odd/sphere.farm/")" -eq 0 ] || fail "parts were written outside the work folder"

echo "== an array over the cluster's MaxArraySize: refused before anything is written or submitted"
if "$tetglow" farm "$scene" --parts 1002 --spp 2000 -o "$dir/big/sphere.exr" 2> "$dir/big.err"; then
    fail "farm accepted 1002 tasks"
fi
cat "$dir/big.err"
grep -q "more than the 1001 a job array may have (the cluster's MaxArraySize" "$dir/big.err" || fail "the refusal does not name the limit"
[ ! -e "$dir/big" ] || fail "farm wrote files for a refused array"

echo "== 4 parts through Slurm against one render, with an account, a time limit, memory, an sbatch option and setup lines"
printf 'echo "preamble ran in $SLURM_JOB_NAME"\n' > "$dir/site.sh"
"$tetglow" farm "$scene" --parts 4 "${options[@]}" --account tetglow-test --time 10 --mem 100M --sbatch-arg=--comment=farm-test \
    --preamble "$dir/site.sh" --setup 'note="it'"'"'s \"set\""; echo "setup: $note"' -o "$dir/farm/sphere.exr" --wait | tee "$dir/farm.out"
for log in task-0.log task-3.log prepare.log merge.log; do
    grep -q '^preamble ran in tetglow-' "$dir/farm/sphere.farm/$log" || fail "$log: the preamble did not run"
    grep -q '^setup: it'"'"'s "set"$' "$dir/farm/sphere.farm/$log" || fail "$log: the setup line did not run as written"
done
cmp "$dir/farm/sphere.exr" "$dir/single.exr" || fail "the farm's image differs from the single render"
[ "$(ls "$dir"/farm/sphere.farm/task-*.log | wc -l)" -eq 4 ] || fail "expected 4 array tasks"
grep -q "read from the cache" "$dir"/farm/sphere.farm/task-0.log || fail "task 0 ran TetGen instead of reading the cache"
jobs=$(sed -n 's/^farm: submitted job \([0-9]*\) .* array \([0-9]*\) .* merge \([0-9]*\) .*/\1 \2 \3/p' "$dir/farm.out")
[ "$(wc -w <<< "$jobs")" -eq 3 ] || fail "no job ids in farm's output"
for job in $jobs; do
    info=$(scontrol show job "$job")
    for field in Account=tetglow-test TimeLimit=00:10:00 MinMemoryNode=100M Comment=farm-test; do
        grep -q "$field" <<< "$info" || fail "job $job ran without $field: $info"
    done
done

echo "== a turntable: frames 1 and 2 of 4, 2 parts each"
sed 's/"camera":/"turntable": {"frames": 4}, "camera":/' "$scene" > "$dir/turntable.json"
turn=(--resolution 16x12 --spp 4 --integrator volpath)
"$tetglow" farm "$dir/turntable.json" --parts 2 --frames 1:3 "${turn[@]}" -o "$dir/turn/t.exr" --wait
for frame in 1 2; do
    "$tetglow" render "$dir/turntable.json" "${turn[@]}" --frame $frame -o "$dir/t$frame.exr" > /dev/null 2>&1
    cmp "$dir/turn/t.000$frame.exr" "$dir/t$frame.exr" || fail "frame $frame differs from its single render"
done
cmp -s "$dir/t1.exr" "$dir/t2.exr" && fail "frames 1 and 2 are the same image"

echo "== a task that cannot write its part"
mkdir -p "$dir/bad/sphere.farm/part-0000-002.exr/in-the-way"
if "$tetglow" farm "$scene" --parts 4 "${options[@]}" -o "$dir/bad/sphere.exr" --wait 2> "$dir/bad.err"; then
    fail "farm succeeded although task 2 failed"
fi
cat "$dir/bad.err"
grep -q "task 2 wrote no part: .*part-0000-002.exr'*: the output must name a file, not a folder" "$dir/bad.err" || fail "the error does not name task 2's failure"
[ ! -e "$dir/bad/sphere.exr" ] || fail "an image was written without task 2's part"
echo "== a medium with no inside: refused before anything is submitted"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n' > "$dir/open.obj"  # a flat square: a sheet
sed 's|{"type": "sphere", "center": \[0, 0, 0\], "radius": 1, "subdivisions": 4}|{"type": "mesh", "file": "open.obj"}|' "$scene" > "$dir/open.json"
grep -q open.obj "$dir/open.json" || fail "the open scene was not made"
if "$tetglow" farm "$dir/open.json" --parts 2 --spp 2 -o "$dir/open/o.exr" --wait 2> "$dir/open.err"; then
    fail "farm succeeded although the medium encloses no volume"
fi
cat "$dir/open.err"
grep -q "open.obj): mesh encloses no volume" "$dir/open.err" || fail "the error does not name the medium's mesh"
grep -q "submitted" "$dir/open.err" && fail "jobs were submitted for a scene farm refuses"
[ ! -e "$dir/open/o.farm" ] || fail "the job scripts were written for a scene farm refuses"
echo "== a tet cache the jobs cannot fill: the cache job fails, the array never runs"
printf 'not a folder\n' > "$dir/cache-file"
if TETGLOW_CACHE_DIR="$dir/cache-file" "$tetglow" farm "$scene" --parts 2 --spp 2 -o "$dir/nocache/n.exr" --wait \
    2> "$dir/nocache.err"; then
    fail "farm succeeded although the cache job failed"
fi
cat "$dir/nocache.err"
grep -q "task 0 wrote no part: it did not run: the tet cache job failed: .*cannot fill the tet cache" "$dir/nocache.err" ||
    fail "the error does not give the cache job's failure"
[ ! -e "$dir/nocache/n.exr" ] || fail "an image was written without parts"
echo "PASS"
