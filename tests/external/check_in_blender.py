"""Imports one RigMesh export into an empty Blender scene and checks that it
arrives as a rigged, animated character matching our own rig and skinning.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_in_blender.py -- EXPORT RIG_JSON EXPECTED_JSON

EXPORT is a .glb, .gltf, .fbx or .dae written by `rigmesh build --pose-demo`,
RIG_JSON the `--rig` file of the same build, EXPECTED_JSON what the
expected_pose helper computed with our engine (model size, bone names, key
times, and a few vertices at rest and skinned at `time`). Prints one line per
check and exits 1 if any check failed (2 on bad arguments).

Coordinates: our parts are Y up, in metres. Blender's world is Z up, so every
importer turns a Y-up file's (x, y, z) into (x, -z, y). Units: glTF is metres;
our FBX says UnitScaleFactor 100 (metres), which Blender's FBX importer turns
into scale 1; Blender's COLLADA importer ignores <unit> unless asked, and ours
says metre anyway. So one Blender unit is one of our units for every format.
"""

import json
import os
import sys

try:
    import numpy
except ImportError:  # Debian's blender does not pull it in; the importers need it
    print("check_in_blender: NumPy is missing in Blender's Python; "
          "install python3-numpy (scripts/setup.sh)")
    sys.exit(1)

# Blender 3.4.1's glTF importer uses np.bool, which NumPy 1.24 removed.
numpy.bool = bool

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bmesh  # noqa: E402  (Blender modules after the NumPy fix)
import bpy  # noqa: E402
from mathutils.kdtree import KDTree  # noqa: E402

# Per format: the Blender frame of time 0 (glTF actions start at frame 0,
# FBX at frame 1, COLLADA at 0) and whether weight sums are checked strictly
# (we normalise for glTF, where the file is the truth; the other importers'
# raw sums are only reported, Blender normalises when deforming).
# EXPECTED_JSON has one vertex set per format (by extension), since the
# exporter cuts the influences per vertex to what each format allows.
FORMATS = {
    ".glb": {"name": "glTF binary", "first_frame": 0.0, "strict_sums": True},
    ".gltf": {"name": "glTF", "first_frame": 0.0, "strict_sums": True},
    ".fbx": {"name": "FBX", "first_frame": 1.0, "strict_sums": False},
    ".dae": {"name": "COLLADA", "first_frame": 0.0, "strict_sums": False},
}
UNIT_SCALE = 1.0  # Blender units per model unit, for every format (see above)


def to_blender(point):
    """Our Y-up model coordinates to Blender's Z-up world."""
    return blender_files.to_blender(point, UNIT_SCALE)


class Report:
    """Collects one line per check; failures decide the exit code."""

    def __init__(self):
        self.failures = 0

    def check(self, name, ok, detail=""):
        print(f"  [{'PASS' if ok else 'FAIL'}] {name}{': ' + detail if detail else ''}")
        self.failures += 0 if ok else 1
        return ok

    def note(self, name, detail):
        print(f"  [INFO] {name}: {detail}")


def import_file(path, extension):
    """Imports into the empty factory scene with each importer's defaults."""
    blender_files.import_file(path)


def keyed_frames(action):
    """Sorted distinct frames (rounded to 1/1000) of every keyframe in the action."""
    frames = set()
    for curve in action.fcurves:
        for point in curve.keyframe_points:
            frames.add(round(point.co.x, 3))
    return sorted(frames)


def mesh_world_positions(obj, mesh):
    matrix = obj.matrix_world
    return [matrix @ vertex.co for vertex in mesh.vertices]


def check_bones(report, armature, rig, names, tolerance):
    """Count, names, parents and heads (world space) against our rig.

    Unless told --no-leaf-bones our exporter adds an end bone `<bone>_end`
    at the tail of every leaf bone (io/ExportRig.h). Such tips are allowed, and checked:
    child of that leaf bone, head at its tail."""
    bones = armature.data.bones
    ours = rig["bones"]
    leaves = {i for i in range(len(ours))} - {b["parent"] for b in ours}
    tips = {names[i] + "_end": i for i in leaves if names[i]}
    got_tips = [bone for bone in bones if bone.name in tips]
    report.check("bone count", len(bones) - len(got_tips) == len(ours),
                 f"{len(bones)} in Blender ({len(got_tips)} of them leaf tips `<bone>_end`), "
                 f"{len(ours)} ours")
    missing = [name or f"our bone {i} (not exported)" for i, name in enumerate(names)
               if not name or name not in bones]
    extra = [bone.name for bone in bones if bone.name not in names and bone.name not in tips]
    report.check("bone names", not missing and not extra,
                 f"missing {missing or 'none'}, unexpected {extra or 'none'}")

    def head_error(bone, joint):
        point = to_blender(rig["joints"][joint]["position"])
        return ((armature.matrix_world @ bone.head_local) - point).length

    wrong_parents, worst_head, worst_name = [], 0.0, ""
    for index, bone in enumerate(ours):
        if not names[index] or names[index] not in bones:
            continue
        got = bones[names[index]]
        parent = names[bone["parent"]] if bone["parent"] >= 0 else None
        got_parent = got.parent.name if got.parent else None
        if got_parent != parent:
            wrong_parents.append(f"{got.name}: {got_parent} instead of {parent}")
        error = head_error(got, bone["head"])
        if error > worst_head:
            worst_head, worst_name = error, got.name
    for tip in got_tips:
        leaf = tips[tip.name]
        got_parent = tip.parent.name if tip.parent else None
        if got_parent != names[leaf]:
            wrong_parents.append(f"{tip.name}: {got_parent} instead of {names[leaf]}")
        error = head_error(tip, ours[leaf]["tail"])
        if error > worst_head:
            worst_head, worst_name = error, tip.name
    report.check("bone parents", not wrong_parents, "; ".join(wrong_parents[:5]) or "all match")
    report.check("bone heads", worst_head <= tolerance,
                 f"largest error {worst_head:.3g} ({worst_name or '-'}), tolerance {tolerance:.3g}")


def check_mesh(report, mesh_object, armature, names, strict_sums):
    """Watertight, bound to the armature, vertex groups = bones, weights."""
    mesh = mesh_object.data
    topology = bmesh.new()
    topology.from_mesh(mesh)
    open_edges = sum(1 for edge in topology.edges if len(edge.link_faces) != 2)
    report.check("watertight", open_edges == 0 and len(topology.faces) > 0,
                 f"{len(topology.verts)} vertices, {len(topology.faces)} faces, "
                 f"{open_edges} edges without exactly 2 faces")
    topology.free()

    modifiers = [m for m in mesh_object.modifiers if m.type == "ARMATURE" and m.object == armature]
    parented = mesh_object.parent == armature and mesh_object.parent_type == "ARMATURE"
    report.check("bound to the armature", bool(modifiers) or parented,
                 f"armature modifier {'yes' if modifiers else 'no'}, "
                 f"armature parent {'yes' if parented else 'no'}")

    groups = {group.name for group in mesh_object.vertex_groups}
    wanted = {name for name in names if name}
    report.check("vertex groups match the bones", groups == wanted and len(wanted) == len(names),
                 f"{len(groups)} groups for {len(names)} bones; "
                 f"missing {sorted(wanted - groups) or 'none'}, "
                 f"not a bone {sorted(groups - wanted) or 'none'}")

    bone_groups = {group.index for group in mesh_object.vertex_groups if group.name in names}
    unweighted, worst_sum, worst_vertex = 0, 0.0, -1
    for vertex in mesh.vertices:
        total = sum(g.weight for g in vertex.groups if g.group in bone_groups and g.weight > 0)
        if total <= 0:
            unweighted += 1
            continue
        if abs(total - 1.0) > worst_sum:
            worst_sum, worst_vertex = abs(total - 1.0), vertex.index
    report.check("every vertex weighted", unweighted == 0, f"{unweighted} of {len(mesh.vertices)} without weight")
    detail = f"largest |sum - 1| {worst_sum:.3g} (vertex {worst_vertex}), tolerance 1e-3"
    if strict_sums:
        report.check("weights sum to 1", worst_sum <= 1e-3, detail)
    else:
        report.note("weight sums (Blender normalises when deforming)", detail)


def find_action(armature):
    if armature.animation_data and armature.animation_data.action:
        return armature.animation_data.action
    return bpy.data.actions[0] if len(bpy.data.actions) else None


def check_animation(report, armature, expected, first_frame):
    """Keyframes at the expected times; returns the frame of expected['time']."""
    fps = bpy.context.scene.render.fps / bpy.context.scene.render.fps_base
    action = find_action(armature)
    if not report.check("animation", action is not None,
                        f"action '{action.name}'" if action else f"{len(bpy.data.actions)} actions"):
        return first_frame + expected["time"] * fps
    frames = keyed_frames(action)
    wanted = [first_frame + t * fps for t in expected["key_times"]]
    missing = [f for f in wanted if not any(abs(f - g) < 0.01 for g in frames)]
    outside = [f for f in frames if f < wanted[0] - 0.01 or f > wanted[-1] + 0.01]

    def shorten(values):
        return values if len(values) <= 8 else values[:4] + ["..."] + values[-2:]

    report.check("keyframes at the clip's times", not missing and not outside,
                 f"expected frames {wanted} at {fps:g} fps, keyed {shorten(frames)} "
                 f"({len(frames)} distinct); missing {missing or 'none'}, "
                 f"outside the clip {shorten(outside) or 'none'}")
    return first_frame + expected["time"] * fps


def deformed_positions(mesh_object, frame):
    """World positions of the armature-deformed mesh at a (fractional) frame."""
    whole = int(frame // 1)
    bpy.context.scene.frame_set(whole, subframe=frame - whole)
    evaluated = mesh_object.evaluated_get(bpy.context.evaluated_depsgraph_get())
    positions = mesh_world_positions(evaluated, evaluated.to_mesh())
    evaluated.to_mesh_clear()
    return positions


def check_deformation(report, mesh_object, samples, first_frame, time, frame, tolerance):
    """Blender's deformed vertices against our engine's skinning: at the first
    key (the rest pose: bind matrices) and at `frame` (the clip's bend).

    Vertices are matched by rest position, since importers may reorder them."""
    rest = mesh_world_positions(mesh_object, mesh_object.data)
    tree = KDTree(len(rest))
    for index, position in enumerate(rest):
        tree.insert(position, index)
    tree.balance()
    matches = [tree.find(to_blender(vertex["rest"])) for vertex in samples]
    worst_rest = max(distance for _, _, distance in matches)
    report.check("sample vertices found at rest", worst_rest <= tolerance,
                 f"{len(samples)} vertices, farthest {worst_rest:.3g} from ours, "
                 f"tolerance {tolerance:.3g}")
    if worst_rest > tolerance:
        return

    at_first_key = deformed_positions(mesh_object, first_frame)
    worst_first = max((at_first_key[index] - to_blender(vertex["rest"])).length
                      for vertex, (_, index, _) in zip(samples, matches))
    report.check(f"rest pose at frame {first_frame:g} (t = 0 s)", worst_first <= tolerance,
                 f"largest error {worst_first:.3g} (tolerance {tolerance:.3g})")

    deformed = deformed_positions(mesh_object, frame)
    worst_pose, worst_moved, lines = 0.0, 0.0, []
    for vertex, (_, index, _) in zip(samples, matches):
        error = (deformed[index] - to_blender(vertex["posed"])).length
        moved = (to_blender(vertex["posed"]) - to_blender(vertex["rest"])).length
        worst_pose, worst_moved = max(worst_pose, error), max(worst_moved, moved)
        lines.append(f"ours #{vertex['index']} -> Blender #{index}: "
                     f"moved {moved:.4g}, off by {error:.3g}")
    report.check(f"deformed vertices at frame {frame:g} (t = {time:g} s)", worst_pose <= tolerance,
                 f"largest error {worst_pose:.3g} (tolerance {tolerance:.3g}); "
                 f"the pose moves them up to {worst_moved:.3g}")
    for line in lines:
        print(f"         {line}")


def main(arguments):
    if len(arguments) != 3:
        print(__doc__)
        return 2
    path, rig_path, expected_path = arguments
    extension = os.path.splitext(path)[1].lower()
    if extension not in FORMATS:
        print(f"check_in_blender: unsupported file type {extension}")
        return 2
    with open(rig_path) as file:
        rig = json.load(file)
    with open(expected_path) as file:
        expected = json.load(file)
    settings = FORMATS[extension]
    tolerance = 1e-3 * expected["model_size"]
    print(f"check_in_blender: {path} ({settings['name']}), Blender {bpy.app.version_string}, "
          f"model size {expected['model_size']:.4g}")

    report = Report()
    bpy.ops.wm.read_factory_settings(use_empty=True)
    try:
        import_file(path, extension)
    except Exception as error:  # the importers raise RuntimeError, and others
        report.check("import", False, f"{type(error).__name__}: {error}")
        print(f"FAIL: {path}: Blender could not import it")
        return 1
    objects = list(bpy.context.scene.objects)
    report.check("import", bool(objects), f"{len(objects)} objects: "
                 + ", ".join(f"{o.name} ({o.type})" for o in objects))

    armatures = [o for o in objects if o.type == "ARMATURE"]
    meshes = [o for o in objects if o.type == "MESH"]
    report.check("exactly one armature", len(armatures) == 1, f"{len(armatures)} armatures")
    report.check("exactly one mesh", len(meshes) == 1, f"{len(meshes)} meshes")
    if len(armatures) != 1 or len(meshes) != 1:
        print(f"FAIL: {path}: {report.failures} failed check(s); stopped before the rig checks")
        return 1
    armature, mesh_object = armatures[0], meshes[0]

    check_bones(report, armature, rig, expected["bone_names"], tolerance)
    check_mesh(report, mesh_object, armature, expected["bone_names"], settings["strict_sums"])
    frame = check_animation(report, armature, expected, settings["first_frame"])
    samples = expected["vertices"][extension[1:]]
    check_deformation(report, mesh_object, samples, settings["first_frame"], expected["time"],
                      frame, tolerance)

    verdict = "FAIL" if report.failures else "PASS"
    print(f"{verdict}: {path}: {report.failures} failed check(s)")
    return 1 if report.failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    code = main(sys.argv[separator + 1:])
    sys.stdout.flush()
    sys.exit(code)
