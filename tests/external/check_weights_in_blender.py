"""Opens a RigMesh export with Blender's default importer and checks that
hand-painted skin weights arrived (they must survive
save, reopen and export to Blender): every vertex of the part within RADIUS of CENTRE
(our Y-up coordinates) has VALUE in the vertex group GROUP, at least
MINIMUM such vertices exist, and every vertex's groups sum to 1.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python check_weights_in_blender.py -- FILE PART GROUP X Y Z RADIUS VALUE MINIMUM
Exits 1 if a check failed, 2 on bad arguments.
"""

import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_files  # noqa: E402
import bpy  # noqa: E402

TOLERANCE = 1e-4  # glTF stores weights as floats; FBX and COLLADA as doubles or text


def main(arguments):
    if len(arguments) != 9:
        print(__doc__)
        return 2
    path, part, group_name = arguments[:3]
    centre = blender_files.to_blender([float(a) for a in arguments[3:6]])
    radius, value, minimum = float(arguments[6]), float(arguments[7]), int(arguments[8])
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    print(f"check_weights_in_blender: {os.path.basename(path)}")
    mesh = bpy.context.scene.objects.get(part)
    group = mesh.vertex_groups.get(group_name) if mesh else None
    if group is None:
        names = [g.name for g in mesh.vertex_groups] if mesh else []
        print(f"  [FAIL] no mesh {part} with a vertex group {group_name} (groups: {names})")
        return 1
    inside = wrong = sums_off = 0
    for vertex in mesh.data.vertices:
        weights = {mesh.vertex_groups[g.group].name: g.weight for g in vertex.groups}
        if abs(sum(weights.values()) - 1.0) > TOLERANCE:
            sums_off += 1
        # A little inside the radius: points on its rim may round either way.
        if (mesh.matrix_world @ vertex.co - centre).length < 0.98 * radius:
            inside += 1
            if abs(weights.get(group_name, 0.0) - value) > TOLERANCE:
                wrong += 1
    checks = [
        (inside >= minimum, f"{inside} painted vertices (at least {minimum})"),
        (wrong == 0, f"{wrong} of them without {group_name} = {value}"),
        (sums_off == 0, f"{sums_off} vertices whose weights do not sum to 1"),
    ]
    for ok, text in checks:
        print(f"  [{'PASS' if ok else 'FAIL'}] {text}")
    return 0 if all(ok for ok, _ in checks) else 1


if __name__ == "__main__":
    separator = sys.argv.index("--") if "--" in sys.argv else len(sys.argv)
    sys.exit(main(sys.argv[separator + 1:]))
