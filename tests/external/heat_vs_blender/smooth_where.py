"""Where the roughest edges are (top 1% of the largest per-bone weight jump),
ours vs Blender: which bone jumps, near which joint, in which region kind.
  blender -b --factory-startup --python smooth_where.py -- OUTDIR SKETCH"""
import collections, json, os, sys
import numpy as np
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cbor_min, limb_metrics as lm

outdir, sketch = sys.argv[sys.argv.index("--") + 1:][:2]
rig = json.load(open(os.path.join(outdir, sketch + ".rig.json")))
bl = json.load(open(os.path.join(outdir, sketch + ".blender.json")))
part = cbor_min.loads(open(os.path.join(outdir, sketch + ".rigmesh"), "rb").read())["parts"][0]["part"]
V = np.array(rig["vertices"]); F = np.array(part["mesh"]["faces"]).reshape(-1, 3)
kind = np.array(part["origins"]["kind"]); nb = len(rig["bones"])
J = np.array([j["position"] for j in rig["joints"]])
E = lm.mesh_edges(F)
for who, ws in (("ours", rig["weights"]), ("blender", bl["weights"])):
    W = lm.dense(ws, nb)
    D = np.abs(W[E[:, 0]] - W[E[:, 1]])
    jump = D.max(axis=1); bone = D.argmax(axis=1)
    p99 = lm.percentile(jump, 0.99)
    top = np.nonzero(jump >= p99)[0]
    mid = 0.5 * (V[E[top, 0]] + V[E[top, 1]])
    near_joint = np.argmin(np.linalg.norm(mid[:, None, :] - J[None], axis=2), axis=1)
    dj = np.linalg.norm(mid - J[near_joint], axis=1)
    kinds = collections.Counter("cyl" if (kind[E[t, 0]] == 0 and kind[E[t, 1]] == 0) else "conn/mixed" for t in top)
    print("%s %s: p99 %.4f, %d edges at or above it; jumping bone %s; nearest joint (index) %s; "
          "distance to it median %.3f; %s" % (sketch, who, p99, len(top),
          dict(collections.Counter(bone[top].tolist())), dict(collections.Counter(near_joint.tolist())),
          float(np.median(dj)), dict(kinds)))
    # Edge length of the top edges vs all edges.
    L = np.linalg.norm(V[E[:, 0]] - V[E[:, 1]], axis=1)
    print("    top edges' length median %.4f vs all edges %.4f; bones at the root joint %d: %s" % (
        float(np.median(L[top])), float(np.median(L)), rig["root"],
        [i for i, b in enumerate(rig["bones"]) if rig["root"] in (b["head"], b["tail"])]))
