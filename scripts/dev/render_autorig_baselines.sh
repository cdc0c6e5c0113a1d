#!/bin/bash
# Rigs each character the auto-rig tests use (the assimp-testmodels
# characters, the meshes made in Blender in tests/data/autorig) with
# `rigmesh rig` and renders the result as Blender imports it
# (scripts/dev/render_rig.py) into docs/images/autorig/NAME_EXT.png: the
# baselines to look at after a change to autorig/.
#
# usage: scripts/dev/render_autorig_baselines.sh [RIGMESH] (default build/dev/app/rigmesh)
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
rigmesh="${1:-$root/build/dev/app/rigmesh}"
out="$root/docs/images/autorig"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
models=/usr/share/assimp/models
for file in "$models/MD2/faerie.md2" "$models/MD2/sydney.md2" "$models/OBJ/WusonOBJ.obj" \
            "$models/COB/dwarf.cob" "$models/BLEND/HUMAN.blend" "$models/OBJ/spider.obj" \
            "$models/IQM/mrfixit.iqm" "$models/Collada/human.zae" \
            "$models/X/fromtruespace_bin32.x" "$models/ASE/MotionCaptureROM.ase" \
            "$root/tests/data/autorig/suzanne.obj" "$root/tests/data/autorig/primitives.obj" \
            "$root/tests/data/autorig/horned.obj" \
            "$root/tests/data/autorig/statue.obj" "$root/tests/data/autorig/armed.obj"; do
    # The extension is part of the name: BLEND/HUMAN.blend and
    # Collada/human.zae would otherwise collide where case does not count.
    base="$(basename "$file")"
    name="${base%.*}_${base##*.}"
    "$rigmesh" rig "$file" -o "$work/$name.glb" --leaf-bones
    blender -b --factory-startup --python-exit-code 1 \
        --python "$root/scripts/dev/render_rig.py" -- "$work/$name.glb" "$out/$name.png" >/dev/null
    echo "$out/$name.png"
done
