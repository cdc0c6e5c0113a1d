"""Opens one of our exports of an imported rig with Blender's default
importer and plays its clip: at each time posed_vertices gave, the meshes
as Blender deforms them (linear blend) lie where the studio's skinning puts
them, every vertex within 1% of the size (a rig from Debian's
assimp-testmodels posed in the studio and in Blender at the same frame).

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_animated_in_blender.py -- EXPORT.glb POSED_JSON
POSED_JSON (posed_vertices with clip "-"): "clip", "rest" and "posed" by
time in seconds; Blender's glTF importer puts time t at frame 24 t.
Exits 1 if a check failed, 2 on bad arguments.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402
from mathutils.kdtree import KDTree  # noqa: E402

TOLERANCE = 0.01


def main(arguments):
    if len(arguments) != 2:
        print(__doc__)
        return 2
    path, posed_path = arguments
    with open(posed_path) as file:
        ours = json.load(file)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    failures = 0

    def check(name, ok, detail):
        nonlocal failures
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}: {detail}")
        failures += 0 if ok else 1

    print(f"check_animated_in_blender: {os.path.basename(path)}, clip {ours['clip']}")
    check("one armature", len(armatures) == 1, f"{len(armatures)}")
    if len(armatures) != 1:
        return 1
    armature = armatures[0]
    actions = [a for a in bpy.data.actions if a.name.startswith(ours["clip"])]
    check("the clip's action", bool(actions), f"{[a.name for a in bpy.data.actions]}")
    if not actions:
        return 1
    armature.animation_data.action = actions[0]
    for track in armature.animation_data.nla_tracks:
        track.mute = True

    rest = [blender_files.to_blender(p) for p in ours["rest"]]
    lo = Vector([min(p[k] for p in rest) for k in range(3)])
    hi = Vector([max(p[k] for p in rest) for k in range(3)])
    size = (hi - lo).length
    armature.data.pose_position = "REST"
    theirs_rest = blender_files.world_vertices()
    armature.data.pose_position = "POSE"
    tree = KDTree(len(rest))
    for index, p in enumerate(rest):
        tree.insert(p, index)
    tree.balance()
    matched = [tree.find(p) for p in theirs_rest]
    worst_rest = max(distance for _, _, distance in matched)
    # Our exporter joins vertices identical in position, normal and weights
    # (docs/EXCHANGE.md, io/AssimpJoinVertices.h): an imported mesh split at a
    # UV seam we do not keep may lose such twins, never a place.
    theirs_tree = KDTree(len(theirs_rest))
    for index, p in enumerate(theirs_rest):
        theirs_tree.insert(p, index)
    theirs_tree.balance()
    worst_back = max(theirs_tree.find(p)[2] for p in rest)
    twins = len(rest) - len({tuple(p) for p in rest})
    check("the meshes at rest",
          len(rest) - twins <= len(theirs_rest) <= len(rest) and
          max(worst_rest, worst_back) <= 1e-4 * size,
          f"{len(theirs_rest)} vertices (ours {len(rest)}, {twins} of them at the place of "
          f"another), each within {max(worst_rest, worst_back) / size:.2g} of the other's")
    for time, posed in ours["posed"].items():
        frame = 24.0 * float(time)
        bpy.context.scene.frame_set(int(math.floor(frame)), subframe=frame - math.floor(frame))
        seen = blender_files.world_vertices()
        worst = max((seen[v] - blender_files.to_blender(posed[index])).length
                    for v, (_, index, _) in enumerate(matched))
        check(f"posed at {float(time):.4g} s (frame {frame:.3g})", worst <= TOLERANCE * size,
              f"largest distance {worst / size:.3g} of the size")
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
