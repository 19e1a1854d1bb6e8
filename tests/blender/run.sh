#!/bin/sh
# Runs the Blender add-on's tests: tests/blender/run.sh TETGLOW_BINARY
# Exit 77 (skipped) when Blender is not installed (./setup.sh test installs it).
tetglow=$1
command -v blender >/dev/null 2>&1 || { echo "SKIP: blender is not installed (./setup.sh test installs it)"; exit 77; }
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/tetglow-blender.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scripts/addons"
ln -s "$here/../../blender/tetglow" "$work/scripts/addons/tetglow"
BLENDER_USER_SCRIPTS="$work/scripts" BLENDER_USER_CONFIG="$work/config" blender -b --factory-startup --python-exit-code 1 \
    --python "$here/test_addon.py" -- "$tetglow" "$work/out" 2>&1
