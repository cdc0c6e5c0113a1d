#!/bin/bash
# Our bone heat against Blender's automatic weights (bone heat) on
# the same mesh and exactly the same bone segments, for every good shared
# sketch: the limb-leak figure, the 99th percentile of the largest per-bone
# weight jump over an edge and the dominant-bone rate (figures ported from
# tests/engine/part/LimbWeightMetrics.h to limb_metrics.py; checked against
# test_part's own output when it is there).
#
#   run.sh RIGMESH SKETCH_DIR OUT_DIR [--check KNOWN_ROUGHER]
#
# Prints the table. With --check, exits 1 when our leak exceeds Blender's on
# any sketch, or our weights are rougher than Blender's on a sketch not in
# the comma-separated KNOWN_ROUGHER list. RESOLVE=1 also re-solves our heat in
# numpy with other heat constants and tapers (resolve.py, a few minutes).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rigmesh="$1"
sketches_dir="$2"
out="$3"
check=""
known=""
if [[ "${4:-}" == "--check" ]]; then
    check=1
    known="${5:-}"
fi
rm -rf "$out" && mkdir -p "$out"

sketches=()
for f in "$sketches_dir"/*.json; do
    name="$(basename "$f" .json)"
    [[ "$name" == bad_* ]] && continue
    sketches+=("$name")
    # Mesh, bones and our weights; and the same part as a document (it has
    # the vertex origins the leak figure needs).
    "$rigmesh" build "$f" -o "$out/$name.obj" --rig "$out/$name.rig.json" > "$out/$name.build.log" 2>&1
    printf '{"format":"rigmesh-recipe","version":3,"steps":[{"command":"sketch","stroke":"%s","name":"%s"}]}\n' \
        "$f" "$name" > "$out/$name.recipe.json"
    "$rigmesh" run "$out/$name.recipe.json" -o "$out/$name.rigmesh" > "$out/$name.run.log" 2>&1
    blender -b --factory-startup --python "$here/blender_autoweights.py" -- \
        "$out/$name.obj" "$out/$name.rig.json" "$out/$name.blender.json" > "$out/$name.blender.log" 2>&1
    if grep -qE "Bone Heat Weighting|Warning:|Error:" "$out/$name.blender.log"; then
        echo "$name: Blender said:"; grep -E "Bone Heat Weighting|Warning:|Error:" "$out/$name.blender.log" | sed "s/^/    /"
    fi
done

blender -b --factory-startup --python "$here/evaluate.py" -- "$out" "${sketches[@]}" > "$out/evaluate.log" 2>&1 \
    || { cat "$out/evaluate.log"; exit 1; }
test_part="${TEST_PART:-$(dirname "$(dirname "$rigmesh")")/tests/test_part}"
if [[ -x "$test_part" ]]; then
    "$test_part" --gtest_filter='*LimbLeak*' > "$out/test_part_limbleak.txt" 2>&1 || true
fi
CHECK="$check" KNOWN_ROUGHER="$known" python3 "$here/table.py" "$out" "${sketches[@]}"
if [[ "${RESOLVE:-0}" == 1 ]]; then
    multi=()
    for s in "${sketches[@]}"; do
        python3 -c "import json,sys; sys.exit(0 if len(json.load(open('$out/$s.metrics.json'))['limbs']) > 1 else 1)" && multi+=("$s")
    done
    blender -b --factory-startup --python "$here/resolve.py" -- "$out" "${multi[@]}" 2>&1 | grep -E '^RESOLVE|rror'
fi
