# Blender check of "export the current pose": the file's
# mesh, as Blender shows it after a default import, must lie where our own
# skinning puts the posed part (the current pose exported as an .obj), within
# 1e-5 of the mesh's size.
#   blender -b --factory-startup --python-exit-code 1 \
#       --python check_posed_in_blender.py -- POSED.(glb|fbx|dae) POSED.obj
import sys

import bpy
from mathutils import kdtree

try:
    import numpy
except ImportError:
    sys.exit("check_posed_in_blender: NumPy is missing (Debian package python3-numpy)")
# Blender 3.4.1's glTF importer uses np.bool, which NumPy 1.24 removed.
numpy.bool = bool

path, obj_path = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
if path.endswith((".glb", ".gltf")):
    bpy.ops.import_scene.gltf(filepath=path)
elif path.endswith(".fbx"):
    bpy.ops.import_scene.fbx(filepath=path)
else:
    bpy.ops.wm.collada_import(filepath=path)

# A file with the pose as a one-key animation (--pose-as-key) shows it once
# the animation is evaluated: any frame, the key holds.
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


def largest_gap(points, others):
    tree = kdtree.KDTree(len(others))
    for i, p in enumerate(others):
        tree.insert(p, i)
    tree.balance()
    return max(tree.find(p)[2] for p in points)


if not seen or not ours:
    sys.exit(f"check_posed_in_blender: no mesh ({len(seen)} vertices in Blender, {len(ours)} ours)")
xs = [p[0] for p in ours]; ys = [p[1] for p in ours]; zs = [p[2] for p in ours]
size = ((max(xs) - min(xs)) ** 2 + (max(ys) - min(ys)) ** 2 + (max(zs) - min(zs)) ** 2) ** 0.5
gap = max(largest_gap(seen, ours), largest_gap(ours, seen))
print(f"{path}: {len(seen)} vertices in Blender, {len(ours)} ours, largest gap {gap:.3g} "
      f"({gap / size:.3g} of the size)")
if gap > 1e-5 * size:
    sys.exit(f"check_posed_in_blender: the posed mesh is {gap:.3g} away from our skinning")
