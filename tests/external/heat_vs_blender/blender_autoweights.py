"""Blender 3.4.1 bone heat ("automatic weights") on our mesh and our bones.

Run: blender -b --factory-startup --python blender_autoweights.py -- MESH.obj RIG.json OUT.json

The mesh is built from the OBJ's vertex and face lists exactly as written
(same vertex order, no importer, no axis conversion); the armature has one
bone per bone of the rig JSON, in its order, named bone<index>, with head and
tail at our joints' positions and our parent relations. Then Object >
Parent > With Automatic Weights, and the normalised vertex-group weights are
written per vertex as [[bone index, weight], ...].
"""
import json
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:]
obj_path, rig_path, out_path = argv

vertices, faces = [], []
with open(obj_path) as f:
    for line in f:
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "f":
            faces.append(tuple(int(p.split("/")[0]) - 1 for p in parts[1:]))

rig = json.load(open(rig_path))
assert len(vertices) == rig["vertex_count"] == len(rig["vertices"]), "vertex counts differ"
worst = max(
    max(abs(a - b) for a, b in zip(v, r)) for v, r in zip(vertices, rig["vertices"]))
assert worst < 1e-6, "OBJ and rig JSON vertices differ by %g" % worst

# Empty scene (factory startup has a cube, a camera and a light).
for obj in list(bpy.data.objects):
    bpy.data.objects.remove(obj, do_unlink=True)

mesh = bpy.data.meshes.new("part")
mesh.from_pydata(vertices, [], faces)
mesh.update()
assert len(mesh.vertices) == len(vertices)
mesh_obj = bpy.data.objects.new("part", mesh)
bpy.context.scene.collection.objects.link(mesh_obj)

# "head", "tail" and "root" are places in "joints" (not joint ids); "parent" is a place in "bones".
joints = [j["position"] for j in rig["joints"]]
bones = rig["bones"]


arm = bpy.data.armatures.new("rig")
arm_obj = bpy.data.objects.new("rig", arm)
bpy.context.scene.collection.objects.link(arm_obj)
bpy.context.view_layer.objects.active = arm_obj
bpy.ops.object.mode_set(mode="EDIT")
edit = []
for i, b in enumerate(bones):
    eb = arm.edit_bones.new("bone%d" % i)
    eb.head = joints[b["head"]]
    eb.tail = joints[b["tail"]]
    eb.use_deform = True
    edit.append(eb)
for i, b in enumerate(bones):
    if b["parent"] >= 0:
        parent = edit[b["parent"]]  # "parent" is a bone index
        edit[i].parent = parent
        # Our child bone starts at its parent's tail joint: connected.
        edit[i].use_connect = (parent.tail - edit[i].head).length < 1e-12
bpy.ops.object.mode_set(mode="OBJECT")
assert len(arm.bones) == len(bones), "Blender dropped a bone (zero length?)"
for i, b in enumerate(bones):
    bb = arm.bones["bone%d" % i]
    h, t = joints[b["head"]], joints[b["tail"]]
    err = max(max(abs(x - y) for x, y in zip(bb.head_local, h)),
              max(abs(x - y) for x, y in zip(bb.tail_local, t)))
    assert err < 1e-5, "bone %d moved by %g" % (i, err)

bpy.ops.object.select_all(action="DESELECT")
mesh_obj.select_set(True)
arm_obj.select_set(True)
bpy.context.view_layer.objects.active = arm_obj
result = bpy.ops.object.parent_set(type="ARMATURE_AUTO")
print("parent_set:", result)

group_bone = {}
for g in mesh_obj.vertex_groups:
    if g.name.startswith("bone"):
        group_bone[g.index] = int(g.name[4:])
weights = []
unweighted = 0
for v in mesh.vertices:
    raw = [(group_bone[g.group], g.weight) for g in v.groups
           if g.group in group_bone and g.weight > 0.0]
    total = sum(w for _, w in raw)
    if total > 0.0:
        weights.append([[b, w / total] for b, w in sorted(raw)])
    else:
        weights.append([])
        unweighted += 1
bones_with_weight = sorted({b for ws in weights for b, _ in ws})
json.dump({"weights": weights, "unweighted_vertices": unweighted,
           "bones_without_weight": [i for i in range(len(bones)) if i not in bones_with_weight]},
          open(out_path, "w"))
print("wrote %s: %d vertices, %d without any weight, bones without weight %s" %
      (out_path, len(weights), unweighted,
       [i for i in range(len(bones)) if i not in bones_with_weight]))
