"""Builds in Blender the rigs riggers make with Rigify and exports each as
.glb, .fbx and .dae with each exporter's default options: the meta-rig
(human: 159 bones, face and fingers, 59 of them disconnected; basic
quadruped: 34 bones, 12 disconnected), a body grown around its bones
(a capsule per bone, voxel-remeshed into one closed surface, decimated)
parented to it With Automatic Weights, and an action "Walk" that turns a
connected bone, a disconnected one and the root and moves the root.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python make_rigify_rigs.py -- OUT_DIR

Writes OUT_DIR/<rig>.glb, .fbx, .dae and <rig>.json for rig in human,
quadruped: every bone (name, parent, connected, head, tail, in Blender's
world, metres), the action's frames and rate, and the body's vertices at
rest and deformed (linear blend, as the armature modifier deforms) at the
checked frames, in Blender's world.
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402, F401  (NumPy for the glTF exporter)
import addon_utils  # noqa: E402
import bpy  # noqa: E402
from mathutils import Quaternion, Vector  # noqa: E402

RIGS = {"human": "armature_human_metarig_add",
        "quadruped": "armature_basic_quadruped_metarig_add"}
FRAMES = (1, 24)
CHECKED_FRAMES = (7, 13, 19)


def meta_rig(operator):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    addon_utils.enable("rigify", default_set=True)
    getattr(bpy.ops.object, operator)()
    rig = bpy.context.active_object
    return rig


def body(rig):
    """One closed surface around the bones: a capsule per bone (radius a
    quarter of its length, 1.5 to 8 cm), joined, voxel remeshed at 7.5 mm,
    decimated to about 12000 faces."""
    capsules = []
    for bone in rig.data.bones:
        head = rig.matrix_world @ bone.head_local
        tail = rig.matrix_world @ bone.tail_local
        length = (tail - head).length
        radius = min(0.08, max(0.015, 0.25 * length))
        bpy.ops.mesh.primitive_cylinder_add(vertices=10, radius=radius, depth=length,
                                            location=(head + tail) / 2)
        cylinder = bpy.context.active_object
        cylinder.rotation_mode = "QUATERNION"
        cylinder.rotation_quaternion = Vector((0, 0, 1)).rotation_difference(tail - head)
        capsules.append(cylinder)
        for end in (head, tail):
            bpy.ops.mesh.primitive_uv_sphere_add(segments=10, ring_count=6, radius=radius,
                                                 location=end)
            capsules.append(bpy.context.active_object)
    bpy.ops.object.select_all(action="DESELECT")
    for capsule in capsules:
        capsule.select_set(True)
    bpy.context.view_layer.objects.active = capsules[0]
    bpy.ops.object.join()
    mesh = bpy.context.active_object
    mesh.name = "Body"
    bpy.ops.object.transform_apply(location=True, rotation=True, scale=True)
    remesh = mesh.modifiers.new("Remesh", "REMESH")
    remesh.mode = "VOXEL"
    remesh.voxel_size = 0.0075
    bpy.ops.object.modifier_apply(modifier=remesh.name)
    decimate = mesh.modifiers.new("Decimate", "DECIMATE")
    decimate.ratio = min(1.0, 12000 / max(1, len(mesh.data.polygons)))
    bpy.ops.object.modifier_apply(modifier=decimate.name)
    return mesh


def parent_with_automatic_weights(mesh, rig):
    bpy.ops.object.select_all(action="DESELECT")
    mesh.select_set(True)
    rig.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.parent_set(type="ARMATURE_AUTO")


def animate(rig):
    """Walk: the root bone moves and turns, a connected bone and a
    disconnected one bend, keyed at frames 1, 12 and 24."""
    bones = rig.data.bones
    root = next(b for b in bones if b.parent is None)
    connected = next(b for b in bones if b.parent is not None and b.use_connect
                     and b.children)
    disconnected = next(b for b in bones if b.parent is not None and not b.use_connect
                        and b.children and b.parent.parent is not None)
    action = bpy.data.actions.new("Walk")
    rig.animation_data_create()
    rig.animation_data.action = action
    keys = {1: 0.0, 12: 1.0, 24: 0.0}
    for name, axis, angle in ((root.name, (0, 0, 1), 25.0), (connected.name, (1, 0, 0), 40.0),
                              (disconnected.name, (0, 0, 1), -35.0)):
        pose_bone = rig.pose.bones[name]
        pose_bone.rotation_mode = "QUATERNION"
        for frame, amount in keys.items():
            pose_bone.rotation_quaternion = Quaternion(axis, math.radians(angle * amount))
            pose_bone.keyframe_insert("rotation_quaternion", frame=frame)
    root_pose = rig.pose.bones[root.name]
    for frame, amount in keys.items():
        root_pose.location = (0.0, 0.1 * amount, 0.0)
        root_pose.keyframe_insert("location", frame=frame)
    bpy.context.scene.frame_start, bpy.context.scene.frame_end = FRAMES
    bpy.context.scene.render.fps = 24
    return [root.name, connected.name, disconnected.name]


def deformed(mesh):
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh.evaluated_get(depsgraph)
    return [list(evaluated.matrix_world @ v.co) for v in evaluated.data.vertices]


def describe(rig, mesh, animated):
    bones = [{"name": b.name, "parent": b.parent.name if b.parent else None,
              "connected": bool(b.use_connect),
              "head": list(rig.matrix_world @ b.head_local),
              "tail": list(rig.matrix_world @ b.tail_local)} for b in rig.data.bones]
    scene = bpy.context.scene
    scene.frame_set(FRAMES[0])
    posed = {}
    for frame in CHECKED_FRAMES:
        scene.frame_set(frame)
        posed[str(frame)] = deformed(mesh)
    scene.frame_set(FRAMES[0])
    rig.data.pose_position = "REST"
    rest = deformed(mesh)
    rig.data.pose_position = "POSE"
    return {"bones": bones, "action": "Walk", "frames": list(FRAMES), "fps": scene.render.fps,
            "animated_bones": animated, "checked_frames": list(CHECKED_FRAMES),
            "rest": rest, "posed": posed}


def main(arguments):
    if len(arguments) != 1:
        print(__doc__)
        return 2
    out = arguments[0]
    os.makedirs(out, exist_ok=True)
    for name, operator in RIGS.items():
        rig = meta_rig(operator)
        mesh = body(rig)
        parent_with_automatic_weights(mesh, rig)
        animated = animate(rig)
        description = describe(rig, mesh, animated)
        bpy.ops.object.select_all(action="DESELECT")
        bpy.ops.export_scene.gltf(filepath=os.path.join(out, name + ".glb"))
        bpy.ops.export_scene.fbx(filepath=os.path.join(out, name + ".fbx"))
        bpy.ops.wm.collada_export(filepath=os.path.join(out, name + ".dae"))
        with open(os.path.join(out, name + ".json"), "w") as file:
            json.dump(description, file)
        print(f"make_rigify_rigs: {name}: {len(rig.data.bones)} bones, "
              f"{len(mesh.data.vertices)} vertices")
    return 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
