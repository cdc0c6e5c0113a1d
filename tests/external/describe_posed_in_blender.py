"""Where Blender puts a rigged file's vertices as its action plays: the file
itself (not our export of it) opened with Blender's default importer, the
armature's action at the given times, linear blend skinning (Blender's
armature modifier by default). compare_posed.py then holds the studio's
pose of the same file (posed_vertices) against it: a rig from Debian's
assimp-testmodels posed in the studio and in Blender at the same frame.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python describe_posed_in_blender.py -- FILE OUT_JSON SECONDS...
Each SECONDS is a time after the action's first key (Blender's glTF
importer puts a file's time t at frame 24 t, its FBX importer at frame
1 + fps t). OUT_JSON, in Blender's world: "rest" (the meshes in the rest
pose), "frames" [first, last], "fps", "checked_frames" and "posed" by frame,
as make_rigify_rigs.py writes them. Exits 1 if the file has not one
armature with an action, 2 on bad arguments.
"""

import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402


def main(arguments):
    if len(arguments) < 3:
        print(__doc__)
        return 2
    path, out_path, seconds = arguments[0], arguments[1], [float(s) for s in arguments[2:]]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    scene = bpy.context.scene
    armatures = [o for o in scene.objects if o.type == "ARMATURE"]
    if len(armatures) != 1 or not armatures[0].animation_data or \
            not armatures[0].animation_data.action:
        print(f"describe_posed_in_blender: {len(armatures)} armatures, no single action")
        return 1
    armature = armatures[0]
    action = armature.animation_data.action
    first, last = action.frame_range
    fps = scene.render.fps / scene.render.fps_base
    armature.data.pose_position = "REST"
    scene.frame_set(int(first))
    rest = [list(p) for p in blender_files.world_vertices()]
    armature.data.pose_position = "POSE"
    posed, checked = {}, []
    for s in seconds:
        frame = first + s * fps
        scene.frame_set(int(frame), subframe=frame - int(frame))
        checked.append(frame)
        posed[str(frame)] = [list(p) for p in blender_files.world_vertices()]
    print(f"describe_posed_in_blender: {os.path.basename(path)}, action {action.name}, "
          f"frames {first:g}-{last:g} at {fps:g} fps, {len(rest)} vertices")
    with open(out_path, "w") as file:
        json.dump({"action": action.name, "frames": [first, last], "fps": fps,
                   "checked_frames": checked, "rest": rest, "posed": posed}, file)
    return 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
