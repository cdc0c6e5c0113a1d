"""Imports one RigMesh export into an empty Blender scene with the importer's
default options and checks what a rigger sees of the armature:
every bone's head on our head, its tail within 1 degree of our
head-to-tail direction, and its length within 1% of ours; no stray empties;
every vertex weighted (also after --subdivide and --decimate).

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_bone_frames_in_blender.py -- EXPORT RIG_JSON [--leaf-bones]

EXPORT is a .glb, .gltf, .fbx or .dae written by `rigmesh build`, RIG_JSON
its `--rig` file. A leaf bone's length reaches Blender only through an end
bone (our exports' default, like Blender's own FBX "Add Leaf Bones") or, in
COLLADA, through Blender's tip extras, which we always write; without them
(`rigmesh build --no-leaf-bones`) Blender's glTF and FBX importers guess it
(the parent's length), so leaf lengths are checked for .dae always and for
the others with --leaf-bones (say so for a file with end bones).
Prints one line per check; exits 1 if any failed (2 on bad arguments).
"""

import json
import math
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402


def import_file(path):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    return blender_files.import_file(path)


def main(arguments):
    if len(arguments) not in (2, 3) or (len(arguments) == 3 and arguments[2] != "--leaf-bones"):
        print(__doc__)
        return 2
    path, rig_path = arguments[0], arguments[1]
    leaf_bones = len(arguments) == 3
    extension = import_file(path)
    rig = json.load(open(rig_path))
    joints = [blender_files.to_blender(j["position"]) for j in rig["joints"]]
    ours = {b["id"]: b for b in rig["bones"]}
    leaves = {b["id"] for b in rig["bones"]} - {
        rig["bones"][b["parent"]]["id"] for b in rig["bones"] if b["parent"] >= 0}
    size = max((a - b).length for a in joints for b in joints) or 1.0
    check_leaf_lengths = leaf_bones or extension == ".dae"
    failures = 0

    def check(name, ok, detail):
        nonlocal failures
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}: {detail}")
        failures += 0 if ok else 1

    print(f"check_bone_frames_in_blender: {os.path.basename(path)}"
          f"{' (leaf bones)' if leaf_bones else ''}")
    objects = bpy.context.scene.objects
    strays = [o.name for o in objects if o.type not in ("ARMATURE", "MESH")]
    check("no stray objects", not strays, ", ".join(strays) or "only armatures and meshes")
    armatures = [o for o in objects if o.type == "ARMATURE"]
    check("one armature", len(armatures) == 1, f"{len(armatures)} armatures")
    if len(armatures) != 1:
        return 1
    armature = armatures[0]

    seen, worst_head, worst_angle, worst_length = set(), (0.0, ""), (0.0, ""), (0.0, "")
    ends = 0
    for bone in armature.data.bones:
        if leaf_bones and bone.name.endswith("_end") and not bone.children:
            ends += 1
            continue
        match = re.search(r"_bone(\d+)$", bone.name)
        if not match or int(match.group(1)) not in ours:
            check("bone names", False, f"unexpected bone {bone.name}")
            continue
        ident = int(match.group(1))
        seen.add(ident)
        head = joints[ours[ident]["head"]]
        tail = joints[ours[ident]["tail"]]
        got_head = armature.matrix_world @ bone.head_local
        got_tail = armature.matrix_world @ bone.tail_local
        error = (got_head - head).length / size
        if error > worst_head[0]:
            worst_head = (error, bone.name)
        angle = math.degrees((got_tail - got_head).angle(tail - head, math.pi))
        if angle > worst_angle[0]:
            worst_angle = (angle, bone.name)
        if ident not in leaves or check_leaf_lengths:
            ratio = abs((got_tail - got_head).length / (tail - head).length - 1.0)
            if ratio > worst_length[0]:
                worst_length = (ratio, bone.name)
    check("every bone", seen == set(ours), f"{len(seen)} of {len(ours)} bones")
    if leaf_bones:
        check("end bones", ends == len(leaves), f"{ends} end bones, {len(leaves)} leaves")
    check("heads", worst_head[0] <= 1e-4,
          f"largest error {worst_head[0]:.2g} of the model's size ({worst_head[1] or '-'})")
    check("tail directions", worst_angle[0] <= 1.0,
          f"largest angle {worst_angle[0]:.3g} degrees ({worst_angle[1] or '-'})")
    meshes = [o for o in objects if o.type == "MESH"]
    unweighted = sum(1 for mesh in meshes for v in mesh.data.vertices
                     if not any(g.weight > 0 for g in v.groups))
    total = sum(len(mesh.data.vertices) for mesh in meshes)
    check("every vertex weighted", total > 0 and unweighted == 0,
          f"{unweighted} of {total} vertices without a bone weight")
    check("lengths" + ("" if check_leaf_lengths else " (leaves: Blender guesses)"),
          worst_length[0] <= 0.01,
          f"largest error {100 * worst_length[0]:.3g}% ({worst_length[1] or '-'})")
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
