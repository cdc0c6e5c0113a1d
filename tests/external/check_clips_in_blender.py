"""Imports a RigMesh export with named clips over several parts
and checks that every clip arrives as its own action on every part's
armature, keyed at our key times, and deforms like our own skinning.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_clips_in_blender.py -- EXPORT EXPECTED_JSON

EXPORT is a .glb or .fbx written by `rigmesh run two_clips.json`,
EXPECTED_JSON what expected_clips computed from the same recipe's document.
Blender makes one action per clip and armature: glTF `<clip>_<armature>`
(one NLA track per glTF animation, named after the clip), FBX
`<armature>|<clip>|` (one per animation stack). Each action in turn is made
the armature's active action (NLA tracks muted) and the mesh evaluated at the
clip's checked time: every sample vertex within 1e-5 of ours.
"""

import json
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402  (fixes NumPy for the importers first)
import bpy  # noqa: E402
from check_in_blender import Report, deformed_positions, keyed_frames  # noqa: E402
from mathutils.kdtree import KDTree  # noqa: E402

FIRST_FRAME = {".glb": 0.0, ".gltf": 0.0, ".fbx": 1.0}  # Blender frame of 0 s
TOLERANCE = 1e-5


def action_of(armature, clip, extension):
    wanted = f"{armature.name}|{clip}|" if extension == ".fbx" else f"{clip}_{armature.name}"
    return bpy.data.actions.get(wanted)


def actions_on(armature, extension):
    if extension == ".fbx":
        return [a for a in bpy.data.actions if a.name.startswith(armature.name + "|")]
    return [a for a in bpy.data.actions if a.name.endswith("_" + armature.name)]


def main(arguments):
    if len(arguments) != 2:
        print(__doc__)
        return 2
    path, expected_path = arguments
    extension = os.path.splitext(path)[1].lower()
    with open(expected_path) as file:
        expected = json.load(file)
    fps = expected["frames_per_second"]
    first = FIRST_FRAME[extension]
    print(f"check_clips_in_blender: {path}, Blender {bpy.app.version_string}")
    report = Report()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.context.scene.render.fps = round(fps)
    blender_files.import_file(path)

    clips = expected["clips"]
    parts = sorted({part for per_part in clips.values() for part in per_part})
    for part in parts:
        armature = bpy.context.scene.objects.get(f"{part}_armature")
        mesh_object = bpy.context.scene.objects.get(part)
        if not report.check(f"{part}: armature and mesh", armature is not None and
                            mesh_object is not None and mesh_object.type == "MESH"):
            continue
        names = sorted(a.name for a in actions_on(armature, extension))
        wanted = sorted(clip for clip, per_part in clips.items() if part in per_part)
        report.check(f"{part}: one action per clip", len(names) == len(wanted),
                     f"actions {names}, clips {wanted}")
        if extension != ".fbx":
            tracks = sorted(t.name for t in armature.animation_data.nla_tracks)
            report.check(f"{part}: one NLA track per clip", tracks == wanted,
                         f"tracks {tracks}")
        rest = [mesh_object.matrix_world @ v.co for v in mesh_object.data.vertices]
        tree = KDTree(len(rest))
        for index, position in enumerate(rest):
            tree.insert(position, index)
        tree.balance()
        for clip in wanted:
            ours = clips[clip][part]
            action = action_of(armature, clip, extension)
            if not report.check(f"{part} / {clip}: action", action is not None,
                                action.name if action else f"none among {names}"):
                continue
            frames = keyed_frames(action)
            keys = [first + t * fps for t in ours["key_times"]]
            missing = [f for f in keys if not any(abs(f - g) < 1e-3 for g in frames)]
            outside = [f for f in frames if f < keys[0] - 1e-3 or f > keys[-1] + 1e-3]
            report.check(f"{part} / {clip}: key frames", not missing and not outside,
                         f"ours {keys}, Blender {frames if len(frames) < 8 else frames[:3] + ['...']}"
                         f" ({len(frames)}); missing {missing or 'none'}, outside {outside or 'none'}")
            # This clip alone drives the armature.
            animation = armature.animation_data
            for track in animation.nla_tracks:
                track.mute = True
            animation.action = action
            samples = ours["vertices"][extension[1:] if extension != ".gltf" else "glb"]
            matches = [tree.find(blender_files.to_blender(v["rest"])) for v in samples]
            worst_rest = max(distance for _, _, distance in matches)
            frame = first + ours["time"] * fps
            positions = deformed_positions(mesh_object, frame)
            worst, moved = 0.0, 0.0
            for vertex, (_, index, _) in zip(samples, matches):
                target = blender_files.to_blender(vertex["posed"])
                worst = max(worst, (positions[index] - target).length)
                moved = max(moved, (target - blender_files.to_blender(vertex["rest"])).length)
            report.check(f"{part} / {clip}: deformed at frame {frame:g} (t = {ours['time']:g} s)",
                         worst_rest <= TOLERANCE and worst <= TOLERANCE and moved > 1e-2,
                         f"{len(samples)} vertices matched within {worst_rest:.2g}, "
                         f"largest error {worst:.2g} (tolerance {TOLERANCE:g}), "
                         f"the pose moves them up to {moved:.3g}")

    verdict = "FAIL" if report.failures else "PASS"
    print(f"{verdict}: {path}: {report.failures} failed check(s)")
    return 1 if report.failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    code = main(sys.argv[separator + 1:])
    sys.stdout.flush()
    sys.exit(code)
