"""Builds in Blender the kind of mesh a user brings from another tool to be
rigged and writes it as plain OBJ, without a rig:

- figure.obj: a metaball figure (a body ball and four limbs of capsules,
  like a starfish standing up), converted to a mesh and triangulated:
  closed, one piece, Blender's own vertex order and triangulation;
- suzanne.obj: Blender's monkey, which is open and of several pieces (its
  eyes apart from the head);
- primitives.obj: a figure joined (Ctrl J) from overlapping primitives
  without a boolean: a torso, a head, two arms and two legs, each a closed
  piece, crossing each other where they meet;
- horned.obj: the primitives' figure whose head wears two horns, cones of
  their own stuck into it, as a helmet's horns come on a character;
- statue.obj: a metaball figure (trunk, head, two arms) standing on the
  ground and cut open at the bottom, as a statue made to stand on a plinth;
- armed.obj: a metaball figure (trunk, head, arms, legs) holding a spear
  upright in its right hand, low on the shaft, and a sword pointing forward
  in its left, each prop its own closed pieces (the sword's grip, crossguard
  and blade) passing through the fist, as a game character comes with its
  weapons.

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
    canonical_face_order(path)


def canonical_face_order(path):
    """Blender 3.4 gives the faces of a joined or converted object in an
    order that changes from run to run (the vertices keep theirs), and the
    auto-rig's result may depend on face order: the faces are written
    sorted, each starting at its smallest vertex (orientation kept), so
    every run checks the same file."""
    with open(path) as f:
        lines = f.read().splitlines()
    faces = []
    others = []
    for line in lines:
        if line.startswith("f "):
            corners = [int(c.split("/")[0]) for c in line.split()[1:]]
            first = corners.index(min(corners))
            faces.append(tuple(corners[first:] + corners[:first]))
        else:
            others.append(line)
    with open(path, "w") as f:
        for line in others:
            f.write(line + "\n")
        for face in sorted(faces):
            f.write("f " + " ".join(str(c) for c in face) + "\n")


def metaballs_to_mesh(name, data):
    """The metaball object made of `data`, converted to a mesh object."""
    obj = bpy.data.objects.new(name, data)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.view_layer.objects.active = obj
    obj.select_set(True)
    bpy.ops.object.convert(target="MESH")
    return bpy.context.active_object


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
    mesh = metaballs_to_mesh("Figure", data)
    export_obj(mesh, os.path.join(out_dir, "figure.obj"))


def suzanne(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_monkey_add()
    export_obj(bpy.context.active_object, os.path.join(out_dir, "suzanne.obj"))


def primitives_figure():
    """A torso, a head, two arms and two legs, each its own object."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.5, location=(0, 0, 1.2), scale=(1, 0.7, 1.4))
    bpy.ops.mesh.primitive_uv_sphere_add(radius=0.32, location=(0, 0, 2.1))
    # (location, rotation about y, depth): arms out sideways, legs down.
    for x, z, angle, depth in [(0.85, 1.55, 1.2, 1.1), (-0.85, 1.55, -1.2, 1.1),
                               (0.25, 0.05, 0.1, 1.3), (-0.25, 0.05, -0.1, 1.3)]:
        bpy.ops.mesh.primitive_cylinder_add(radius=0.13, depth=depth, location=(x, 0, z),
                                            rotation=(0, angle, 0))


def primitives(out_dir):
    primitives_figure()
    bpy.ops.object.select_all(action="SELECT")
    bpy.context.view_layer.objects.active = bpy.context.selected_objects[0]
    bpy.ops.object.join()
    export_obj(bpy.context.active_object, os.path.join(out_dir, "primitives.obj"))


def horned(out_dir):
    """The primitives' figure whose head wears two horns, cones of their own
    pointing up and out, stuck into the head without a boolean."""
    primitives_figure()
    for side in (1, -1):
        bpy.ops.mesh.primitive_cone_add(radius1=0.09, depth=0.45,
                                        location=(side * 0.3, 0, 2.4),
                                        rotation=(0, side * 0.7, 0))
    bpy.ops.object.select_all(action="SELECT")
    bpy.context.view_layer.objects.active = bpy.context.selected_objects[0]
    bpy.ops.object.join()
    export_obj(bpy.context.active_object, os.path.join(out_dir, "horned.obj"))


def statue(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    import bmesh
    import mathutils
    data = bpy.data.metaballs.new("Statue")
    data.resolution = 0.1
    data.render_resolution = 0.1
    # (centre, radius, capsule end or None): trunk, head, two arms.
    trunk = data.elements.new(type="CAPSULE")
    trunk.co = (0, 0, 0.9)
    trunk.radius = 0.45
    trunk.size_x = 0.6
    trunk.rotation = mathutils.Vector((1, 0, 0)).rotation_difference(mathutils.Vector((0, 0, 1)))
    head = data.elements.new()
    head.co = (0, 0, 2.1)
    head.radius = 0.45
    for side in (1, -1):
        arm = data.elements.new(type="CAPSULE")
        arm.co = (side * 0.75, 0, 1.25)
        arm.radius = 0.22
        arm.size_x = 0.45
        arm.rotation = mathutils.Vector((1, 0, 0)).rotation_difference(
            mathutils.Vector((side, 0, -0.6)).normalized())
    mesh = metaballs_to_mesh("Statue", data)
    # Open at the bottom: the faces below the plinth's top are deleted.
    b = bmesh.new()
    b.from_mesh(mesh.data)
    bmesh.ops.delete(b, geom=[f for f in b.faces if f.calc_center_median().z < 0.45],
                     context="FACES")
    b.to_mesh(mesh.data)
    b.free()
    export_obj(mesh, os.path.join(out_dir, "statue.obj"))


def capsule(data, co, radius, half_length, direction):
    import mathutils
    element = data.elements.new(type="CAPSULE")
    element.co = co
    element.radius = radius
    element.size_x = half_length
    element.rotation = mathutils.Vector((1, 0, 0)).rotation_difference(
        mathutils.Vector(direction).normalized())


def armed(out_dir):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    data = bpy.data.metaballs.new("Armed")
    data.resolution = 0.08
    data.render_resolution = 0.08
    capsule(data, (0, 0, 1.5), 0.38, 0.45, (0, 0, 1))
    head = data.elements.new()
    head.co = (0, 0, 2.45)
    head.radius = 0.42
    for side in (1, -1):
        capsule(data, (side * 0.7, 0, 1.65), 0.18, 0.4, (side, 0, -0.6))
        capsule(data, (side * 0.25, 0, 0.6), 0.2, 0.5, (0, 0, 1))
    body = metaballs_to_mesh("Armed", data)
    # The hands are the arms' far ends, about (+-1.04, 0, 1.44).
    bpy.ops.mesh.primitive_cylinder_add(radius=0.05, depth=1.9, location=(1.06, 0, 1.99))
    bpy.ops.mesh.primitive_cylinder_add(radius=0.045, depth=0.42, location=(-1.06, 0.02, 1.44),
                                        rotation=(1.5708, 0, 0))
    bpy.ops.mesh.primitive_cube_add(location=(-1.06, 0.25, 1.44), scale=(0.2, 0.03, 0.04))
    bpy.ops.mesh.primitive_cube_add(location=(-1.06, 0.8, 1.44), scale=(0.06, 0.52, 0.012))
    bpy.ops.object.select_all(action="SELECT")
    bpy.context.view_layer.objects.active = body
    bpy.ops.object.join()
    export_obj(bpy.context.active_object, os.path.join(out_dir, "armed.obj"))


if __name__ == "__main__":
    out = sys.argv[sys.argv.index("--") + 1]
    os.makedirs(out, exist_ok=True)
    figure(out)
    suzanne(out)
    primitives(out)
    statue(out)
    armed(out)
    horned(out)
