"""`rigmesh rig` on every mesh file of Debian's assimp-testmodels, as a new
user would try meshes made elsewhere: each is rigged, or refused with a
clear message for a reason nothing can be done about. Refusals allowed:
the importer cannot read the file (Assimp's own message: a broken, empty or
unsupported file; over the import's memory limit), it holds no triangle
mesh or no face, a non-finite number, every part in it is rigged already. Anything else fails the test: a crash or a
hang (no exit within TIMEOUT seconds), a refusal for crossing faces, holes,
pieces or any other reason (the rig itself refuses a part that fails
Part::validate: weights finite, non-negative and summing to 1 on every
vertex, on bones the skeleton has), a rigged file whose document is not
written.

usage: python3 rig_every_assimp_model.py RIGMESH MODELS_DIR OUT_DIR
"""

import os
import re
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

TIMEOUT = 120
# File names the importers take as meshes (case-insensitive), as listed by
# `dpkg -L assimp-testmodels`; textures, materials and sidecar files are not.
EXTENSIONS = {
    "3d", "3ds", "ac", "amf", "ase", "b3d", "blend", "cob", "csm", "dae",
    "dxf", "fbx", "glb", "gltf", "hmp", "ifc", "irrmesh", "lwo", "m3d",
    "md2", "md3", "md5mesh", "mdl", "ms3d", "nff", "obj", "off", "ogex",
    "ply", "q3o", "q3s", "raw", "smd", "stl", "ter", "x", "x3d", "xgl",
    "zgl",
}
ALLOWED_REFUSALS = [
    re.compile(r'^rigmesh: Cannot import "'),
    re.compile(r"has nothing to rig: every part in it already has a skeleton"),
    re.compile(r"has no surface to rig\."),
]


def mesh_files(models):
    for directory, _, names in os.walk(models):
        for name in sorted(names):
            if name.rsplit(".", 1)[-1].lower() in EXTENSIONS:
                yield os.path.join(directory, name)


def rig(rigmesh, path, out_dir, index):
    out = os.path.join(out_dir, f"model_{index}.rigmesh")
    try:
        run = subprocess.run([rigmesh, "rig", path, "-o", out], capture_output=True,
                             text=True, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return path, "hang", f"no exit within {TIMEOUT} s"
    message = (run.stdout + run.stderr).strip().replace("\n", " ")
    if run.returncode == 0:
        written = os.path.isfile(out) and os.path.getsize(out) > 0
        if os.path.isfile(out):
            os.remove(out)
        return path, "rigged" if written else "unwritten", message[:200]
    if run.returncode == 1 and any(r.search(message) for r in ALLOWED_REFUSALS):
        return path, "refused", message[:200]
    return path, f"failed (exit {run.returncode})", message[:300]


def main():
    rigmesh, models, out_dir = sys.argv[1:4]
    os.makedirs(out_dir, exist_ok=True)
    files = sorted(mesh_files(models))
    if not files:
        sys.exit(f"rig_every_assimp_model: no mesh files under {models}")
    with ThreadPoolExecutor(max_workers=2) as pool:
        outcomes = list(pool.map(lambda item: rig(rigmesh, item[1], out_dir, item[0]),
                                 enumerate(files)))
    counts = {}
    for path, outcome, message in outcomes:
        counts[outcome] = counts.get(outcome, 0) + 1
        print(f"{outcome:10s} {os.path.relpath(path, models)}: {message}")
    print(", ".join(f"{count} {outcome}" for outcome, count in sorted(counts.items())))
    bad = [o for o in outcomes if o[1] not in ("rigged", "refused")]
    if bad:
        sys.exit("rig_every_assimp_model: " + "; ".join(
            f"{os.path.relpath(p, models)} {o}: {m}" for p, o, m in bad))


if __name__ == "__main__":
    main()
