"""Imports one RigMesh export into an empty Blender scene with the importer's
default options and checks that every bone's tail, as Blender placed it,
lies inside the imported meshes: what a rigger sees when a bone pokes out of
its limb. End bones (written by default; `--no-leaf-bones` leaves them out)
are bones in Blender and are checked too.

Inside by ray-cast parity: a point is inside when rays from it cross the
surface an odd number of times; three rays in fixed directions vote, so that
a ray grazing an edge does not decide alone.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_tails_inside_in_blender.py -- EXPORT...

Each EXPORT is a .glb, .gltf, .fbx or .dae written by `rigmesh build`, `rigmesh
rig` or `rigmesh export`, imported alone into an empty scene (several files
share one start of Blender, which costs more than an import). Prints per file
a summary and one line per bone outside (its distance to the surface in
percent of the model's size); exits 1 if any tail of any file is outside
(2 on bad arguments).
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402
from mathutils import Vector  # noqa: E402
from mathutils.bvhtree import BVHTree  # noqa: E402

# Directions in no plane of the axes, so that rays rarely run along a face.
RAY_DIRECTIONS = [Vector(d).normalized() for d in
                  ((0.267, 0.534, 0.802), (-0.7, 0.1, 0.3), (0.2, -0.9, -0.35))]


def world_surface():
    """Every mesh of the scene in world space, at rest (the armature
    modifier's rest pose is the mesh data): a BVH tree and the vertices."""
    vertices, polygons = [], []
    for obj in bpy.context.scene.objects:
        if obj.type != "MESH":
            continue
        base = len(vertices)
        vertices += [obj.matrix_world @ v.co for v in obj.data.vertices]
        polygons += [[base + i for i in p.vertices] for p in obj.data.polygons]
    return BVHTree.FromPolygons(vertices, polygons), vertices


def crossings(tree, point, direction, step):
    """How often the ray from `point` crosses the surface. A hit on the same
    polygon again (single-precision rounding after stepping past it) is one
    crossing."""
    count, origin, last = 0, point.copy(), None
    while True:
        location, _, index, _ = tree.ray_cast(origin, direction)
        if location is None:
            return count
        if index != last:
            count += 1
        last = index
        origin = location + direction * step


def is_inside(tree, point, step):
    odd = sum(crossings(tree, point, d, step) % 2 for d in RAY_DIRECTIONS)
    return odd * 2 > len(RAY_DIRECTIONS)


def check(path):
    """0 when every bone tail of the file lies inside its meshes, else 1."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    tree, vertices = world_surface()
    if not vertices:
        print(f"check_tails_inside_in_blender: {os.path.basename(path)}: no mesh imported")
        return 1
    low = Vector([min(v[k] for v in vertices) for k in range(3)])
    high = Vector([max(v[k] for v in vertices) for k in range(3)])
    size = (high - low).length
    step = 1e-5 * size
    outside, total = [], 0
    for armature in (o for o in bpy.context.scene.objects if o.type == "ARMATURE"):
        for bone in armature.data.bones:
            total += 1
            tail = armature.matrix_world @ bone.tail_local
            if not is_inside(tree, tail, step):
                distance = tree.find_nearest(tail)[3]
                outside.append(f"{bone.name} ({100 * distance / size:.2g}% of the size)")
    print(f"check_tails_inside_in_blender: {os.path.basename(path)}: "
          f"{len(outside)} of {total} bone tails outside the mesh")
    for line in outside:
        print(f"  [FAIL] tail outside: {line}")
    if total == 0:
        print("  [FAIL] no bones imported")
        return 1
    return 1 if outside else 0


def main(arguments):
    if not arguments:
        print(__doc__)
        return 2
    failures = [path for path in arguments if check(path) != 0]
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
