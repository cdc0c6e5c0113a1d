"""Builds in Blender the kind of mesh a user brings from another tool to be
rigged and writes it as plain OBJ, without a rig:

- figure.obj: a metaball figure (a body ball and four limbs of capsules,
  like a starfish standing up), converted to a mesh and triangulated:
  closed, one piece, Blender's own vertex order and triangulation;
- suzanne.obj: Blender's monkey, which is open and of several pieces (its
  eyes): a mesh the rig must refuse by name.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python make_blender_meshes.py -- OUT_DIR
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402, F401
import bpy  # noqa: E402

# (x, z) of each limb's far end, from the body's centre at the origin.
LIMBS = [(1.6, 0.9), (-1.6, 0.9), (0.7, -1.8), (-0.7, -1.8)]


def export_obj(obj, path):
    bpy.ops.object.select_all(action="DESELECT")
    obj.select_set(True)
    bpy.context.view_layer.objects.active = obj
    bpy.ops.wm.obj_export(filepath=path, export_selected_objects=True,
                          export_materials=False, export_uv=False,
                          export_normals=False, export_triangulated_mesh=True)


def figure(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    data = bpy.data.metaballs.new("Figure")
    data.resolution = 0.12
    data.render_resolution = 0.12
    body = data.elements.new()
    body.co = (0, 0, 0)
    body.radius = 0.9
    for x, z in LIMBS:
        # A capsule from the body towards (x, z): metaball capsules lie
        # along their local x, half as long as size_x each way.
        limb = data.elements.new(type="CAPSULE")
        limb.co = (x / 2, 0, z / 2)
        limb.radius = 0.45
        length = (x * x + z * z) ** 0.5
        limb.size_x = length / 2
        import mathutils
        limb.rotation = mathutils.Vector((1, 0, 0)).rotation_difference(
            mathutils.Vector((x, 0, z)).normalized())
    obj = bpy.data.objects.new("Figure", data)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    bpy.ops.object.convert(target="MESH")
    mesh = bpy.context.active_object
    export_obj(mesh, os.path.join(out_dir, "figure.obj"))


def suzanne(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_monkey_add()
    export_obj(bpy.context.active_object, os.path.join(out_dir, "suzanne.obj"))


if __name__ == "__main__":
    out = sys.argv[sys.argv.index("--") + 1]
    os.makedirs(out, exist_ok=True)
    figure(out)
    suzanne(out)
