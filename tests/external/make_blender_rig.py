"""Builds in Blender the rig a user would make by hand and exports it as .glb,
.fbx and .dae with each exporter's default options: a
capsule 3 units tall standing on the origin, skinned (automatic weights) to
an armature "Rig" of three chained bones Lower, Middle, Upper (1 unit each,
up the capsule), and an action "Wave" that bends Middle by 40 degrees about
X at frame 12 and back at frame 24.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python make_blender_rig.py -- OUT_DIR

Writes OUT_DIR/capsule.glb, capsule.fbx, capsule.dae and capsule.json (the
bone names, heads and tails in Blender's world, in metres, and the action).
"""

import json
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402, F401  (NumPy for the glTF exporter)
import bpy  # noqa: E402

BONES = [("Lower", 0.0, 1.0), ("Middle", 1.0, 2.0), ("Upper", 2.0, 3.0)]


def build():
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_cylinder_add(vertices=12, radius=0.35, depth=3.0,
                                        location=(0, 0, 1.5))
    capsule = bpy.context.active_object
    capsule.name = "Capsule"
    bpy.ops.object.mode_set(mode="EDIT")
    bpy.ops.mesh.subdivide(number_cuts=5)
    bpy.ops.object.mode_set(mode="OBJECT")

    bpy.ops.object.armature_add(enter_editmode=True, location=(0, 0, 0))
    rig = bpy.context.active_object
    rig.name = "Rig"
    rig.data.name = "Rig"
    bones = rig.data.edit_bones
    bones.remove(bones[0])
    parent = None
    for name, z0, z1 in BONES:
        bone = bones.new(name)
        bone.head = (0, 0, z0)
        bone.tail = (0, 0, z1)
        bone.parent = parent
        bone.use_connect = parent is not None
        parent = bone
    bpy.ops.object.mode_set(mode="OBJECT")

    bpy.ops.object.select_all(action="DESELECT")
    capsule.select_set(True)
    rig.select_set(True)
    bpy.context.view_layer.objects.active = rig
    bpy.ops.object.parent_set(type="ARMATURE_AUTO")

    action = bpy.data.actions.new("Wave")
    rig.animation_data_create()
    rig.animation_data.action = action
    middle = rig.pose.bones["Middle"]
    middle.rotation_mode = "QUATERNION"
    for frame, angle in ((1, 0.0), (12, 40.0), (24, 0.0)):
        half = math.radians(angle) / 2
        middle.rotation_quaternion = (math.cos(half), math.sin(half), 0, 0)
        middle.keyframe_insert("rotation_quaternion", frame=frame)
    bpy.context.scene.frame_start, bpy.context.scene.frame_end = 1, 24
    return rig


def main(arguments):
    if len(arguments) != 1:
        print(__doc__)
        return 2
    out = arguments[0]
    os.makedirs(out, exist_ok=True)
    build()
    bpy.ops.export_scene.gltf(filepath=os.path.join(out, "capsule.glb"))
    bpy.ops.export_scene.fbx(filepath=os.path.join(out, "capsule.fbx"))
    bpy.ops.wm.collada_export(filepath=os.path.join(out, "capsule.dae"))
    description = {
        "bones": [{"name": name, "head": [0, 0, z0], "tail": [0, 0, z1]}
                  for name, z0, z1 in BONES],
        "action": "Wave", "frames": [1, 24], "fps": bpy.context.scene.render.fps,
    }
    with open(os.path.join(out, "capsule.json"), "w") as file:
        json.dump(description, file, indent=2)
    print("make_blender_rig: wrote", ", ".join(sorted(os.listdir(out))))
    return 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
