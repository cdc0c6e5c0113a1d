"""Opens, with Blender's default importers, a Rigify rig Blender exported
(make_rigify_rigs.py) and the same rig after a trip through RigMesh
(`rigmesh import`, `rigmesh export` to the same format), and checks that
Blender sees our file as it sees its own: the same bones (names, parents,
connected flags (FBX, which stores none: each head as far from its parent's
tail), heads and tails within 1e-4 of the rig's size), an action
named as the original's over the same frames, and the body deformed at the
checked frames as Blender deforms the source scene (linear blend, within
1% of the size). Blender's own file is held to the deformation too, so a
loss of the format itself shows there first.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_rigify_in_blender.py -- ORIGINAL OURS RIG_JSON
Exits 1 if a check failed, 2 on bad arguments.
"""

import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402
from mathutils.kdtree import KDTree  # noqa: E402

BONE_TOLERANCE = 1e-4  # of the size
POSE_TOLERANCE = 0.01  # of the size


def read(path):
    """Imports `path` into an empty scene: its bones in the world, its
    actions, and the armature and body."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
    meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
    if len(armatures) != 1 or len(meshes) != 1:
        raise RuntimeError(f"{os.path.basename(path)}: {len(armatures)} armatures and "
                           f"{len(meshes)} meshes, wanted one each")
    armature = armatures[0]
    bones = {b.name: {"parent": b.parent.name if b.parent else None,
                      "connected": bool(b.use_connect),
                      "head": armature.matrix_world @ b.head_local,
                      "tail": armature.matrix_world @ b.tail_local}
             for b in armature.data.bones}
    return armature, meshes[0], bones


def gap(bones, name):
    """How far a bone's head lies from its parent's tail."""
    return (bones[name]["head"] - bones[bones[name]["parent"]]["tail"]).length


def deformed(mesh):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh.evaluated_get(depsgraph)
    return [evaluated.matrix_world @ v.co for v in evaluated.data.vertices]


def walk_action(armature):
    """The action made from the source's "Walk" (each importer names it its
    own way: glTF `Walk_<armature>`, FBX `<armature>|Walk`, COLLADA after the
    bones), made the armature's active action."""
    actions = [a for a in bpy.data.actions if "Walk" in a.name] or list(bpy.data.actions)
    if not actions:
        return None
    action = actions[0]
    armature.animation_data_create()
    armature.animation_data.action = action
    for track in armature.animation_data.nla_tracks:
        track.mute = True
    return action


def deformation_error(armature, mesh, description, frames, size):
    """The largest distance, over the checked frames, between the body as
    Blender deforms this import and the source scene's body."""
    rest_tree = KDTree(len(description["rest"]))
    for index, point in enumerate(description["rest"]):
        rest_tree.insert(Vector(point), index)
    rest_tree.balance()
    armature.data.pose_position = "REST"
    ours_rest = deformed(mesh)
    armature.data.pose_position = "POSE"
    matched = [rest_tree.find(p) for p in ours_rest]
    worst_rest = max(distance for _, _, distance in matched)
    worst = 0.0
    for frame in frames:
        bpy.context.scene.frame_set(frame)
        posed = deformed(mesh)
        expected = description["posed"][str(frame)]
        for v, (_, index, _) in enumerate(matched):
            worst = max(worst, (posed[v] - Vector(expected[index])).length)
    return worst_rest / size, worst / size


def main(arguments):
    if len(arguments) != 3:
        print(__doc__)
        return 2
    original, ours, description_path = arguments
    with open(description_path) as file:
        description = json.load(file)
    points = [Vector(p) for p in description["rest"]]
    lo = Vector([min(p[k] for p in points) for k in range(3)])
    hi = Vector([max(p[k] for p in points) for k in range(3)])
    size = (hi - lo).length
    failures = 0

    def check(name, ok, detail):
        nonlocal failures
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}: {detail}")
        failures += 0 if ok else 1

    print(f"check_rigify_in_blender: {os.path.basename(original)} and {os.path.basename(ours)}")
    frames = description["checked_frames"]
    results = {}
    for label, path in (("Blender's file", original), ("ours", ours)):
        armature, mesh, bones = read(path)
        action = walk_action(armature)
        keyed = sorted({round(p.co.x, 3) for c in action.fcurves for p in c.keyframe_points}) \
            if action else []
        rest_error, pose_error = deformation_error(armature, mesh, description, frames, size)
        results[label] = (bones, action.name if action else None, keyed)
        check(f"{label}: the body deformed as the source's at frames {frames}",
              pose_error <= POSE_TOLERANCE,
              f"rest within {rest_error:.2g}, posed within {pose_error:.3g} of the size")
    (theirs, their_action, their_keys), (mine, my_action, my_keys) = \
        results["Blender's file"], results["ours"]
    check("bone names", sorted(theirs) == sorted(mine),
          f"{len(mine)} bones, {len(theirs)} in Blender's file; only ours: "
          f"{sorted(set(mine) - set(theirs))[:5]}, only theirs: {sorted(set(theirs) - set(mine))[:5]}")
    common = [name for name in theirs if name in mine]
    parents = [n for n in common if theirs[n]["parent"] != mine[n]["parent"]]
    check("parents", not parents, f"{len(parents)} differ: {parents[:5]}")
    connected = [n for n in common if theirs[n]["connected"] != mine[n]["connected"]]
    if original.lower().endswith(".fbx"):
        # FBX has no "connected" flag: Blender's importer connects a child whose
        # head equals its parent's computed tail to a relative 1e-6 in single
        # precision (import_fbx.py, similar_values_iter), so the flag flips on
        # rounding, in Blender's own file too (against the source rig's flags
        # it differs in as many bones as ours does). What a file can carry is
        # where each head lies relative to its parent's tail: that must agree.
        source = {b["name"]: b["connected"] for b in description["bones"]}
        gaps = [n for n in common if theirs[n]["parent"] is not None and
                abs(gap(theirs, n) - gap(mine, n)) > BONE_TOLERANCE * size]
        check("head to parent's tail", not gaps,
              f"{len(gaps)} bones differ by more than {BONE_TOLERANCE} of the size: {gaps[:5]} "
              f"(connected flags, which FBX does not store: {len(connected)} differ from Blender's "
              f"file; against the source rig ours differ in "
              f"{sum(1 for n in source if n in mine and mine[n]['connected'] != source[n])}, "
              f"Blender's in {sum(1 for n in source if n in theirs and theirs[n]['connected'] != source[n])})")
    else:
        check("connected flags", not connected,
              f"{sum(b['connected'] for b in mine.values())} connected; {len(connected)} differ: "
              f"{connected[:5]}")
    worst, where = 0.0, None
    worst_end, where_end, end_bones = 0.0, None, 0
    for name in common:
        leaf = mine[name]["parent"]
        if name.endswith("_end") and leaf == name[:-len("_end")] and theirs[name]["parent"] == leaf:
            # An end bone (FBX "Add Leaf Bones"): Blender's importer gives it
            # its leaf's length along its own axis. Blender's own end bones
            # point on, out of the limb; ours point back along the leaf and
            # end on its head, inside (io/ExportRig.h endBoneOf). Heads (the
            # leaf's tail) must agree with Blender's file.
            end_bones += 1
            error = (mine[name]["tail"] - mine[leaf]["head"]).length / size
            if error > worst_end:
                worst_end, where_end = error, name
            ends = ("head",)
        else:
            ends = ("head", "tail")
        for end in ends:
            error = (theirs[name][end] - mine[name][end]).length / size
            if error > worst:
                worst, where = error, f"{name} {end}"
    check("heads and tails", worst <= BONE_TOLERANCE, f"largest difference {worst:.3g} of the size "
          f"({where}; end bones: heads only)")
    check("end bones back along their leaves", worst_end <= BONE_TOLERANCE,
          f"{end_bones} end bones, tail farthest from its leaf's head by {worst_end:.3g} of the size "
          f"({where_end or '-'})")
    check("action", my_action is not None and their_action is not None,
          f"ours {my_action}, Blender's {their_action}")
    check("keyed frames", my_keys[:1] == their_keys[:1] and my_keys[-1:] == their_keys[-1:],
          f"ours {my_keys[:1]}..{my_keys[-1:]}, Blender's {their_keys[:1]}..{their_keys[-1:]}")
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
