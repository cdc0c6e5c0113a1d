"""Opens a several-part RigMesh export with Blender's default importer and
checks that every part arrives: a mesh object named after
the part, bound (Armature modifier) to an armature with bones. In glTF and
FBX each part has its own armature `<part>_armature`; Blender's COLLADA
importer makes one armature for all (see AssimpSceneBuilder.cpp).

With --bones=N, the file must hold exactly the parts named (no other mesh
object) and each armature N bones: the merged camel is one mesh
over one armature.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_parts_in_blender.py -- FILE [--bones=N] PART...
Exits 1 if a check failed, 2 on bad arguments.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402


def main(arguments):
    if len(arguments) < 2:
        print(__doc__)
        return 2
    path, parts = arguments[0], arguments[1:]
    bones = None
    if parts and parts[0].startswith("--bones="):
        bones = int(parts[0].split("=", 1)[1])
        parts = parts[1:]
    bpy.ops.wm.read_factory_settings(use_empty=True)
    extension = blender_files.import_file(path)
    objects = bpy.context.scene.objects
    failures = 0
    print(f"check_parts_in_blender: {os.path.basename(path)}")
    for part in parts:
        mesh = objects.get(part)
        modifiers = [m for m in mesh.modifiers if m.type == "ARMATURE"] if mesh else []
        armature = modifiers[0].object if modifiers else None
        ok = mesh is not None and mesh.type == "MESH" and armature is not None and \
            len(armature.data.bones) > 0
        if ok and extension != ".dae":
            ok = armature.name == part + "_armature" and mesh.parent == armature
        if ok and bones is not None:
            ok = len(armature.data.bones) == bones
        detail = (f"bound to {armature.name} ({len(armature.data.bones)} bones)" if armature
                  else "missing or unbound")
        print(f"  [{'PASS' if ok else 'FAIL'}] part {part}: {detail}")
        failures += 0 if ok else 1
    if bones is not None:
        meshes = sorted(o.name for o in objects if o.type == "MESH")
        ok = meshes == sorted(parts)
        print(f"  [{'PASS' if ok else 'FAIL'}] mesh objects: {meshes}")
        failures += 0 if ok else 1
    return 1 if failures else 0


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
