"""Blender check of a mesh made in Blender, rigged by `rigmesh rig`:
what an artist sees after a default import of the rigged file.

- one armature whose leaf bones are the figure's limbs (LEAVES of them);
- every bone's head, middle and tail inside the surface (not for a mesh
  rigged on a wrapped proxy, PROXY given: its pieces and open sheets bound
  no volume; test_autorig checks the bones inside the proxy);
- every vertex weighted, its weights summing to 1;
- turning a leaf bone 45 degrees in pose mode moves its limb and leaves the
  rest where it was: at most MOVED_SHARE of the vertices move, and none of
  the vertices nearest another leaf bone's tail (ten of them, of the piece
  the nearest one belongs to, nearer to that tail than to any other).

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_autorig_in_blender.py -- RIGGED.(glb|fbx|dae) LEAVES [PROXY]
"""

import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402
from mathutils import Matrix, kdtree  # noqa: E402

MOVED_SHARE = 0.5


def fail(message):
    sys.exit(f"check_autorig_in_blender: {message}")


arguments = sys.argv[sys.argv.index("--") + 1:]
path, leaves = arguments[:2]
leaves = int(leaves)
on_proxy = len(arguments) > 2 and arguments[2] == "PROXY"
bpy.ops.wm.read_factory_settings(use_empty=True)
blender_files.import_file(path)
armatures = [o for o in bpy.context.scene.objects if o.type == "ARMATURE"]
meshes = [o for o in bpy.context.scene.objects if o.type == "MESH"]
if len(armatures) != 1 or len(meshes) != 1:
    fail(f"{len(armatures)} armatures and {len(meshes)} meshes, expected one of each")
rig, mesh = armatures[0], meshes[0]
# Leaf end bones (FBX/COLLADA "_end" helpers) are not bones of ours.
bones = [b for b in rig.data.bones if not b.name.endswith("_end")]
leaf_bones = [b for b in bones if not [c for c in b.children if not c.name.endswith("_end")]]
print(f"{path}: {len(bones)} bones, {len(leaf_bones)} leaves, "
      f"{len(mesh.data.vertices)} vertices")
if len(leaf_bones) != leaves:
    fail(f"{len(leaf_bones)} leaf bones, expected {leaves} (one per limb)")

# Inside: the closest surface point's normal points away from the bone point.
inverse = mesh.matrix_world.inverted()
for bone in [] if on_proxy else bones:
    head = rig.matrix_world @ bone.head_local
    tail = rig.matrix_world @ bone.tail_local
    for t in (0.0, 0.5, 1.0):
        p = inverse @ head.lerp(tail, t)
        found, closest, normal, _ = mesh.closest_point_on_mesh(p)
        if not found or (p - closest).dot(normal) > 0:
            fail(f"bone {bone.name} at {t:.1f} of its length lies outside the surface")

groups = {g.index: g.name for g in mesh.vertex_groups}
for v in mesh.data.vertices:
    total = sum(g.weight for g in v.groups if groups.get(g.group) in rig.data.bones)
    if abs(total - 1.0) > 1e-3:
        fail(f"vertex {v.index} has weights summing to {total:.4f}")


def posed_vertices():
    bpy.context.view_layer.update()
    depsgraph = bpy.context.evaluated_depsgraph_get()
    evaluated = mesh.evaluated_get(depsgraph).to_mesh()
    return [mesh.matrix_world @ v.co for v in evaluated.vertices]


rest = posed_vertices()
tree = kdtree.KDTree(len(rest))
for i, p in enumerate(rest):
    tree.insert(p, i)
tree.balance()
size = max((a - b).length for a in rest[:200] for b in rest[:200])


def pieces():
    """Each vertex's piece: connected by edges, over vertices at one place
    (a file's split seams)."""
    piece = list(range(len(rest)))

    def find(i):
        while piece[i] != i:
            piece[i] = piece[piece[i]]
            i = piece[i]
        return i

    def join(a, b):
        piece[find(a)] = find(b)

    for edge in mesh.data.edges:
        join(*edge.vertices)
    for i, p in enumerate(rest):
        for _, j, _ in tree.find_range(p, 1e-6 * size):
            join(i, j)
    return [find(i) for i in range(len(rest))]


piece_of = pieces()
tails = {b.name: rig.matrix_world @ b.tail_local for b in leaf_bones}


def nearest_tail(i):
    return min(tails, key=lambda name: (rest[i] - tails[name]).length)


# The tip of each limb: the vertices nearest its leaf's tail, ten of them, of
# the piece the nearest one belongs to, and each nearer to that tail than to
# any other leaf's. A limb modelled as a piece of fewer vertices (the
# faerie's wings are sheets of eight) is its tip whole, and the next
# vertices nearest its tail belong to another limb; where two tails are
# close (feet side by side) a vertex among both's ten nearest is the tip of
# the nearer one only.
tips = {}
for b in leaf_bones:
    nearest = tree.find_n(tails[b.name], 10)
    tips[b.name] = [i for _, i, _ in nearest
                    if piece_of[i] == piece_of[nearest[0][1]] and nearest_tail(i) == b.name]
for bone in leaf_bones:
    pose_bone = rig.pose.bones[bone.name]
    pose_bone.rotation_mode = "XYZ"
    pose_bone.rotation_euler = (math.radians(45), 0, 0)
    posed = posed_vertices()
    moved = [i for i, (a, b) in enumerate(zip(rest, posed)) if (a - b).length > 1e-3 * size]
    pose_bone.rotation_euler = (0, 0, 0)
    tip_moved = any(i in moved for i in tips[bone.name])
    others = [i for name, ids in tips.items() if name != bone.name for i in ids if i in moved]
    print(f"  {bone.name}: {len(moved)} vertices moved")
    if not tip_moved:
        fail(f"turning {bone.name} does not move its limb's tip")
    if len(moved) > MOVED_SHARE * len(rest):
        fail(f"turning {bone.name} moves {len(moved)} of {len(rest)} vertices")
    if others:
        fail(f"turning {bone.name} moves {len(others)} tip vertices of other limbs")
print(f"{path}: rigged figure checked in Blender")
