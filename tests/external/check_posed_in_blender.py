# Blender check of "export the current pose": the file's
# mesh, as Blender shows it after a default import, must lie where our own
# skinning puts the posed part (the current pose exported as an .obj), within
# 1e-5 of the mesh's size (--tolerance: another fraction of the size).
# --preserve-volume turns on the Armature modifiers' "Preserve Volume"
# (Blender's dual quaternion skinning) before the mesh is read.
#   blender -b --factory-startup --python-exit-code 1 \
#       --python check_posed_in_blender.py -- POSED.(glb|fbx|dae) POSED.obj \
#       [--tolerance F] [--preserve-volume]
import sys

import bpy
from mathutils import kdtree

try:
    import numpy
except ImportError:
    sys.exit("check_posed_in_blender: NumPy is missing (Debian package python3-numpy)")
# Blender 3.4.1's glTF importer uses np.bool, which NumPy 1.24 removed.
numpy.bool = bool

arguments = sys.argv[sys.argv.index("--") + 1:]
path, obj_path = arguments[:2]
tolerance = 1e-5
if "--tolerance" in arguments:
    tolerance = float(arguments[arguments.index("--tolerance") + 1])
preserve_volume = "--preserve-volume" in arguments
bpy.ops.wm.read_factory_settings(use_empty=True)
if path.endswith((".glb", ".gltf")):
    bpy.ops.import_scene.gltf(filepath=path)
elif path.endswith(".fbx"):
    bpy.ops.import_scene.fbx(filepath=path)
else:
    bpy.ops.wm.collada_import(filepath=path)

# A file with the pose as a one-key animation (--pose-as-key) shows it once
# the animation is evaluated: any frame, the key holds.
for obj in bpy.context.scene.objects:
    for modifier in obj.modifiers:
        if modifier.type == "ARMATURE":
            modifier.use_deform_preserve_volume = preserve_volume
bpy.context.scene.frame_set(bpy.context.scene.frame_current)
depsgraph = bpy.context.evaluated_depsgraph_get()
seen = []
for obj in bpy.context.scene.objects:
    if obj.type == "MESH":
        mesh = obj.evaluated_get(depsgraph).to_mesh()
        seen += [obj.matrix_world @ v.co for v in mesh.vertices]

# Ours: y up; Blender's importers turn y up into z up: (x, y, z) -> (x, -z, y).
ours = []
with open(obj_path) as f:
    for line in f:
        if line.startswith("v "):
            x, y, z = map(float, line.split()[1:4])
            ours.append((x, -z, y))


def gaps(points, others):
    """Per point of `points`, the distance to the nearest of `others`."""
    tree = kdtree.KDTree(len(others))
    for i, p in enumerate(others):
        tree.insert(p, i)
    tree.balance()
    return [tree.find(p)[2] for p in points]


if not seen or not ours:
    sys.exit(f"check_posed_in_blender: no mesh ({len(seen)} vertices in Blender, {len(ours)} ours)")
xs = [p[0] for p in ours]; ys = [p[1] for p in ours]; zs = [p[2] for p in ours]
size = ((max(xs) - min(xs)) ** 2 + (max(ys) - min(ys)) ** 2 + (max(zs) - min(zs)) ** 2) ** 0.5
both = sorted(gaps(seen, ours) + gaps(ours, seen))
gap = both[-1]
p99 = both[int(0.99 * (len(both) - 1))]
skinning = "Preserve Volume" if preserve_volume else "linear blend"
print(f"{path} ({skinning}): {len(seen)} vertices in Blender, {len(ours)} ours, largest gap "
      f"{gap:.3g} ({100 * gap / size:.3g}% of the size), 99th percentile {100 * p99 / size:.3g}%")
if gap > tolerance * size:
    sys.exit(f"check_posed_in_blender: the posed mesh is {gap:.3g} away from our skinning "
             f"({100 * gap / size:.3g}% of the size, allowed {100 * tolerance:.3g}%)")
