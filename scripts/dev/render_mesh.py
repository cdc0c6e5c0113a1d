#!/usr/bin/env python3
"""Renders an OBJ mesh from three directions into one PNG, for a quick look.

Flat-shaded painter's algorithm written as SVG and rasterised by ImageMagick:
python3's standard library only. Usage: render_mesh.py MESH.obj OUT.png [X Y R]
(with X Y R only the faces whose centre lies within R of (X, Y) in the sketch
plane are drawn, for a close look at a fold).
"""
import math
import subprocess
import sys


def read_obj(path):
    vertices, faces = [], []
    for line in open(path):
        parts = line.split()
        if not parts:
            continue
        if parts[0] == "v":
            vertices.append(tuple(float(x) for x in parts[1:4]))
        elif parts[0] == "f":
            faces.append(tuple(int(p.split("/")[0]) - 1 for p in parts[1:4]))
    return vertices, faces


def rotate(v, yaw, pitch):
    x, y, z = v
    x, z = x * math.cos(yaw) + z * math.sin(yaw), -x * math.sin(yaw) + z * math.cos(yaw)
    y, z = y * math.cos(pitch) - z * math.sin(pitch), y * math.sin(pitch) + z * math.cos(pitch)
    return x, y, z


def view_svg(vertices, faces, yaw, pitch, ox, size, wire):
    rv = [rotate(v, yaw, pitch) for v in vertices]
    used = sorted({i for f in faces for i in f})  # the drawn faces frame the view
    xs = [rv[i][0] for i in used]
    ys = [rv[i][1] for i in used]
    cx, cy = (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2
    scale = 0.9 * size / max(max(xs) - min(xs), max(ys) - min(ys), 1e-12)
    polys = []
    for f in faces:
        a, b, c = (rv[i] for i in f)
        u = [b[k] - a[k] for k in range(3)]
        w = [c[k] - a[k] for k in range(3)]
        n = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
        length = math.sqrt(sum(x * x for x in n)) or 1.0
        nz = n[2] / length  # towards the viewer (+z)
        if nz <= 0:
            continue
        depth = (a[2] + b[2] + c[2]) / 3
        shade = int(60 + 180 * nz)
        pts = " ".join(
            f"{ox + size / 2 + (p[0] - cx) * scale:.2f},{size / 2 - (p[1] - cy) * scale:.2f}" for p in (a, b, c))
        polys.append((depth, pts, shade))
    polys.sort()
    stroke = 'stroke="#335" stroke-width="0.3"' if wire else 'stroke="none"'
    return "".join(
        f'<polygon points="{p}" fill="rgb({s},{s},{min(255, s + 20)})" {stroke}/>' for _, p, s in polys)


def main():
    vertices, faces = read_obj(sys.argv[1])
    if len(sys.argv) >= 6:
        x, y, r = (float(a) for a in sys.argv[3:6])

        def near(f):
            cx = sum(vertices[i][0] for i in f) / 3
            cy = sum(vertices[i][1] for i in f) / 3
            return (cx - x) ** 2 + (cy - y) ** 2 <= r * r

        faces = [f for f in faces if near(f)]
    size = 600
    views = [(0, 0), (math.pi / 2, 0), (0.6, -0.5)]
    body = "".join(view_svg(vertices, faces, yaw, pitch, i * size, size, True) for i, (yaw, pitch) in enumerate(views))
    svg = f'<svg xmlns="http://www.w3.org/2000/svg" width="{3 * size}" height="{size}"><rect width="100%" height="100%" fill="white"/>{body}</svg>'
    tmp = sys.argv[2] + ".svg"
    open(tmp, "w").write(svg)
    subprocess.run(["convert", tmp, sys.argv[2]], check=True)


if __name__ == "__main__":
    main()
