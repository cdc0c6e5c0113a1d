#!/usr/bin/env python3
"""Renders a rigged file as Blender imports it: the mesh see-through, the
bones in red, the leaf bones' tails in green, in Blender's Front, Right and
Top views, side by side in one PNG.

Blender (its default importer for .glb, .gltf, .fbx or .dae) reads the file;
the world-space triangles and bones are drawn as SVG and rasterised by
ImageMagick's `convert` (Debian package imagemagick). For a look at an
auto-rig's limbs, not a pixel test.

usage: blender -b --factory-startup --python-exit-code 1 \
           --python scripts/dev/render_rig.py -- RIGGED.(glb|fbx|dae) OUT.png
"""
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))


def read_in_blender(path):
    """Every mesh's triangles and every armature's bones (not the `_end`
    helpers of leaf bones), world space, Z up."""
    sys.path.insert(0, os.path.join(HERE, "..", "..", "tests", "external"))
    import blender_files
    import bpy
    bpy.ops.wm.read_factory_settings(use_empty=True)
    blender_files.import_file(path)
    depsgraph = bpy.context.evaluated_depsgraph_get()
    vertices, triangles, bones = [], [], []
    for o in bpy.context.scene.objects:
        if o.type == "MESH":
            mesh = o.evaluated_get(depsgraph).to_mesh()
            mesh.calc_loop_triangles()
            base = len(vertices)
            vertices += [list(o.matrix_world @ v.co) for v in mesh.vertices]
            triangles += [[base + i for i in t.vertices] for t in mesh.loop_triangles]
        elif o.type == "ARMATURE":
            for b in o.data.bones:
                if b.name.endswith("_end"):
                    continue
                leaf = not [c for c in b.children if not c.name.endswith("_end")]
                bones.append({"head": list(o.matrix_world @ b.head_local),
                              "tail": list(o.matrix_world @ b.tail_local), "leaf": leaf})
    return {"vertices": vertices, "triangles": triangles, "bones": bones}


def project(p, view):
    x, y, z = p
    # Blender's Front (numpad 1), Right (numpad 3) and Top (numpad 7) views.
    return {"Front": (x, z), "Right": (y, z), "Top": (x, y)}[view]


def draw(data, png):
    size = 600
    views = ["Front", "Right", "Top"]
    svg = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{3 * size}" height="{size}">'
           '<rect width="100%" height="100%" fill="white"/>']
    points = data["vertices"] + [b[k] for b in data["bones"] for k in ("head", "tail")]
    for k, view in enumerate(views):
        flat = [project(p, view) for p in points]
        xs, ys = [p[0] for p in flat], [p[1] for p in flat]
        cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
        scale = 0.9 * size / max(max(xs) - min(xs), max(ys) - min(ys), 1e-12)

        def to_svg(p):
            u, v = project(p, view)
            return k * size + size / 2 + (u - cx) * scale, size / 2 - (v - cy) * scale

        screen = [to_svg(p) for p in data["vertices"]]
        for t in data["triangles"]:
            corners = " ".join(f"{screen[i][0]:.1f},{screen[i][1]:.1f}" for i in t)
            svg.append(f'<polygon points="{corners}" fill="#4060a0" fill-opacity="0.05" '
                       'stroke="#4060a0" stroke-opacity="0.2" stroke-width="0.4"/>')
        for b in data["bones"]:
            (x1, y1), (x2, y2) = to_svg(b["head"]), to_svg(b["tail"])
            svg.append(f'<line x1="{x1:.1f}" y1="{y1:.1f}" x2="{x2:.1f}" y2="{y2:.1f}" '
                       'stroke="red" stroke-width="2.5"/>')
            svg.append(f'<circle cx="{x1:.1f}" cy="{y1:.1f}" r="3" fill="black"/>')
            if b["leaf"]:
                svg.append(f'<circle cx="{x2:.1f}" cy="{y2:.1f}" r="6" fill="green"/>')
        svg.append(f'<text x="{k * size + 10}" y="20" font-family="sans-serif" '
                   f'font-size="16">{view}</text>')
    leaves = sum(1 for b in data["bones"] if b["leaf"])
    svg.append(f'<text x="10" y="{size - 10}" font-family="sans-serif" font-size="16">'
               f'{len(data["bones"])} bones, {leaves} leaves (green)</text></svg>')
    with tempfile.NamedTemporaryFile("w", suffix=".svg", delete=False) as f:
        f.write("\n".join(svg))
    # No date or time chunks: a render of the same rig is the same file.
    subprocess.run(["convert", f.name, "-define", "png:exclude-chunks=date,time", png], check=True)
    os.unlink(f.name)


def main():
    path, png = sys.argv[sys.argv.index("--") + 1:][:2]
    draw(read_in_blender(path), png)


if __name__ == "__main__":
    main()
