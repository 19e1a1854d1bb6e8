#!/bin/sh
# Zips the add-on into an installable file: blender/package.sh [OUT.zip] (default build/tetglow-blender.zip).
# Install it in Blender: Edit > Preferences > Add-ons > Install..., then tick "Render: tetglow".
set -eu
here=$(cd "$(dirname "$0")" && pwd)
out=${1:-$here/../build/tetglow-blender.zip}
mkdir -p "$(dirname "$out")"
python3 - "$here" "$out" <<'PY'
import os, sys, zipfile
here, out = sys.argv[1], sys.argv[2]
with zipfile.ZipFile(out, 'w', zipfile.ZIP_DEFLATED) as z:
    for name in sorted(os.listdir(os.path.join(here, 'tetglow'))):
        if name.endswith('.py'):
            z.write(os.path.join(here, 'tetglow', name), 'tetglow/' + name)
print(out)
PY
