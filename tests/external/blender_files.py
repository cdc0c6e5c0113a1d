"""What the Blender check scripts share: importing one of our exports with
each importer's default options, and our coordinates in Blender's world."""

import os
import sys

try:
    import numpy
except ImportError:  # Debian's blender does not pull it in; the importers need it
    print("NumPy is missing in Blender's Python; install python3-numpy (scripts/setup.sh)")
    sys.exit(1)
numpy.bool = bool  # Blender 3.4.1's glTF add-on uses np.bool, which NumPy 1.24 removed

from mathutils import Vector  # noqa: E402


def to_blender(point, scale=1.0):
    """Our Y-up model coordinates to Blender's Z-up world: every importer
    turns a Y-up file's (x, y, z) into (x, -z, y)."""
    x, y, z = point
    return Vector((x, -z, y)) * scale


def import_file(path):
    """Imports into the current scene with the importer's defaults; returns
    the file's extension (lower case)."""
    import bpy
    extension = os.path.splitext(path)[1].lower()
    if extension in (".glb", ".gltf"):
        bpy.ops.import_scene.gltf(filepath=path)
    elif extension == ".fbx":
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.wm.collada_import(filepath=path)
    return extension


def world_vertices():
    """Every mesh's vertices as the scene deforms them now, in Blender's world."""
    import bpy
    depsgraph = bpy.context.evaluated_depsgraph_get()
    points = []
    for obj in bpy.context.scene.objects:
        if obj.type == "MESH":
            evaluated = obj.evaluated_get(depsgraph)
            points += [evaluated.matrix_world @ v.co for v in evaluated.data.vertices]
    return points
