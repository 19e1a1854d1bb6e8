#!/usr/bin/env bash
# volpath of two builds at equal time on blub and sphere (2 threads): RMSE against a 384-spp
# render of the old build, and exr_compare.py's block z-test of the two 15 s renders (Blender).
# Usage: bench/studies/volpath_before_after.sh OLD_TETGLOW NEW_TETGLOW OUT_DIR
set -u
cd "$(dirname "$0")/../.."
old=$1 new=$2 o=$3
mkdir -p "$o"
for scene in blub sphere; do
  res=200x200; [ $scene = sphere ] && res=128x128
  [ -f "$o/$scene-ref.exr" ] || "$old" render scenes/$scene.json --spp 384 --resolution $res --threads 2 --seed 99 -o "$o/$scene-ref.exr" >/dev/null 2>&1
  for T in 5 15; do
    for b in old new; do
      bin=$old seed=1; [ $b = new ] && bin=$new seed=2
      log=$("$bin" render scenes/$scene.json --time $T --resolution $res --threads 2 --seed $seed -o "$o/$scene-$b-$T.exr" 2>&1 | tail -1)
      rmse=$("$new" diff "$o/$scene-$b-$T.exr" "$o/$scene-ref.exr" --json | python3 -c 'import json,sys; print(json.load(sys.stdin)["rmse"])')
      echo "$scene $b --time $T: $log | rmse $rmse"
    done
  done
  echo "$scene new vs old, 15 s: $(blender -b --factory-startup --python bench/studies/exr_compare.py -- "$o/$scene-new-15.exr" "$o/$scene-old-15.exr" --block 10 2>&1 | grep EXR_COMPARE)"
done
