"""Opens, with Blender's default importer, the Blender rig of
make_blender_rig.py after a trip through RigMesh (`rigmesh import`, then
`rigmesh export` to the same format) and checks that Blender sees what it
exported: bones Lower, Middle and Upper, chained, with
their heads and tails where they were (metres), the capsule 3 units tall,
and the action (named Wave, except from COLLADA, whose Blender exporter
names it after the object) with its keys.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_blender_rig_in_blender.py -- FILE CAPSULE_JSON
Exits 1 if a check failed, 2 on bad arguments.
"""

import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402


def main(arguments):
    if len(arguments) != 2:
        print(__doc__)
        return 2
    path, description_path = arguments
    description = json.load(open(description_path))
    bpy.ops.wm.read_factory_settings(use_empty=True)
    extension = blender_files.import_file(path)
    failures = 0

    def check(name, ok, detail):
        nonlocal failures
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}: {detail}")
        failures += 0 if ok else 1

    print(f"check_blender_rig_in_blender: {os.path.basename(path)}")
    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    check("one armature, one mesh", len(armatures) == 1 and len(meshes) == 1,
          f"{len(armatures)} armatures, {len(meshes)} meshes")
    if len(armatures) != 1 or len(meshes) != 1:
        return 1
    armature, mesh = armatures[0], meshes[0]
    bones = armature.data.bones
    wanted = [b["name"] for b in description["bones"]]
    got = [b.name for b in bones if not b.name.endswith("_end")]
    check("bone names", sorted(got) == sorted(wanted), f"{sorted(got)}, wanted {sorted(wanted)}")
    parents = {b.name: b.parent.name if b.parent else None for b in bones if b.name in wanted}
    check("bone chain", parents == {"Lower": None, "Middle": "Lower", "Upper": "Middle"},
          str(parents))
    worst = 0.0
    for bone in description["bones"]:
        if bone["name"] not in bones:
            continue
        ours = bones[bone["name"]]
        for end, point in (("head", ours.head_local), ("tail", ours.tail_local)):
            error = ((armature.matrix_world @ point) - Vector(bone[end])).length
            worst = max(worst, error)
    check("bone heads and tails", worst <= 0.01, f"largest error {worst:.3g} m")
    heights = [(mesh.matrix_world @ v.co).z for v in mesh.data.vertices]
    check("mesh height", abs(max(heights) - min(heights) - 3.0) <= 0.01 and abs(min(heights)) <= 0.01,
          f"from {min(heights):.4g} to {max(heights):.4g} m")
    action = armature.animation_data.action if armature.animation_data else None
    names = [a.name for a in bpy.data.actions]
    if extension == ".dae":
        check("an action", action is not None or bool(names), f"actions {names}")
    else:
        check("action Wave", action is not None and "Wave" in action.name, f"actions {names}")
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
