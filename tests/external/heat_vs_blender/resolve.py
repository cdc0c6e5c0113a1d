"""Our bone heat (core/engine/rig/BoneHeatSolver.cpp + HeatTerms.h) re-solved in
numpy (dense), to measure what one change of its terms does to the figures.
First checks that the default options reproduce the weights rigmesh wrote.
  blender -b --factory-startup --python resolve.py -- OUTDIR SKETCH [SKETCH ...]
Variants: heat constant c (1 = ours, 4/3 = Blender's area factor), taper, the
tie tolerance (ours 3e-3: the closest-bone lists, made at 1e-2 for the
figures, are cut down to it).
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cbor_min  # noqa: E402
import limb_metrics as lm  # noqa: E402

K_MIN_SINE = 1e-8
K_MIN_D2_PER_AREA = 1e-12


def solve_weights(V, F, closest, nb, c=1.0, taper_end=0.05, taper_start=0.1, tie=3e-3):
    n = len(V)
    A = np.zeros((n, n))
    area = np.zeros(n)
    for face in F:
        i0, i1, i2 = face
        a, b, cc = V[i0], V[i1], V[i2]
        lengths = sorted([np.linalg.norm(b - a), np.linalg.norm(cc - b), np.linalg.norm(a - cc)])
        da = np.linalg.norm(np.cross(b - a, cc - a))
        assert len({i0, i1, i2}) == 3 and da > 0 and da >= K_MIN_SINE * lengths[1] * lengths[2], \
            "degenerate face: not handled by this re-solve"
        for k in range(3):
            i, j, l = face[k], face[(k + 1) % 3], face[(k + 2) % 3]
            area[i] += 0.5 * da
            e1, e2 = V[j] - V[i], V[l] - V[i]
            hc = 0.5 * (e1 @ e2) / da
            A[j, l] -= hc
            A[l, j] -= hc
            A[j, j] += hc
            A[l, l] += hc
    closest = [[(b, dd) for b, dd in cl if dd <= min(x for _, x in cl) * (1 + tie)]
               for cl in closest]
    heat = np.zeros(n)
    for v in range(n):
        d = min(dd for _, dd in closest[v])
        heat[v] = c * area[v] / max(d * d, K_MIN_D2_PER_AREA * area[v])
    A[np.diag_indices(n)] += heat
    rhs = np.zeros((n, nb))
    for v in range(n):
        for b, _ in closest[v]:
            rhs[v, b] += heat[v] / len(closest[v])
    S = np.linalg.solve(A, rhs)
    weights = []
    for v in range(n):
        ws = []
        for b in range(nb):
            w = S[v, b]
            if not (w >= taper_end) or not (w > 0):
                continue
            if w < taper_start:
                w = taper_start * (w - taper_end) / (taper_start - taper_end)
            if w > 0:
                ws.append((b, w))
        if not ws:
            best = min(closest[v], key=lambda e: e[1])[0]
            ws = [(best, 1.0)]
        t = sum(w for _, w in ws)
        weights.append([(b, w / t) for b, w in ws])
    return weights


def run(outdir, sketch, variants):
    rig = json.load(open(os.path.join(outdir, sketch + ".rig.json")))
    part = cbor_min.loads(open(os.path.join(outdir, sketch + ".rigmesh"), "rb").read())["parts"][0]["part"]
    V = np.array(part["mesh"]["vertices"], dtype=float).reshape(-1, 3)
    F = np.array(part["mesh"]["faces"], dtype=np.int64).reshape(-1, 3)
    skd = part["skeleton"]
    jpos = np.array(skd["joints"]["positions"]).reshape(-1, 3)
    bones = list(zip(skd["bones"]["ids"], skd["bones"]["heads"], skd["bones"]["tails"]))
    sk = lm.Skeleton(list(zip(skd["joints"]["ids"], jpos)), bones, skd["root"])
    nb = len(bones)
    if nb < 2:
        return
    idx = {i: k for k, (i, _h, _t) in enumerate(bones)}
    visible, _ = lm.closest_visible_bones(V, F, sk.segments())
    # The solver's closest bones: the construction's where known, visibility elsewhere.
    known = part["knownClosestByBoneId"]
    solver_closest = []
    for v in range(len(V)):
        flat = known[v]
        lst = [(idx[flat[k]], float(flat[k + 1])) for k in range(0, len(flat), 2)]
        solver_closest.append(lst if lst else visible[v])
    cyl = [k == 0 for k in part["origins"]["kind"]]
    ours = lm.dense(rig["weights"], nb)
    for name, kw in variants:
        kw = dict(kw)
        closest = visible if kw.pop("all_visible", False) else solver_closest
        w = solve_weights(V, F, closest, nb, **kw)
        diff = float(np.abs(lm.dense(w, nb) - ours).max())
        print("RESOLVE %-10s %-22s leak %5d p99 %.5f dom %.4f  (max |w - rigmesh's w| %.2g)" % (
            sketch, name, lm.limb_leak(V, sk, w, visible, cyl),
            lm.largest_bone_jump_p99(F, w, nb), lm.dominant_is_closest_visible_rate(w, visible),
            diff), flush=True)


VARIANTS = [
    ("ours", {}),
    ("c=4/3 (Blender area)", {"c": 4.0 / 3.0}),
    ("taper .025-.05 (Blender)", {"taper_end": 0.025, "taper_start": 0.05}),
    ("tie 1e-4 (Blender)", {"tie": 1e-4}),
    # Visibility tested on every vertex instead of the construction shortcut.
    ("all visible", {"all_visible": True}),
]

if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:]
    only = os.environ.get("VARIANTS")  # e.g. VARIANTS="ours,tie 1e-4 (Blender)"
    chosen = [v for v in VARIANTS if not only or v[0] in only.split(",")]
    for s in argv[1:]:
        run(argv[0], s, chosen)
