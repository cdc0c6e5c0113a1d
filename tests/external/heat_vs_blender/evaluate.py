"""The limb leak and smoothness figures for our weights and Blender's, per sketch.

Run inside Blender's Python (numpy):
  blender -b --factory-startup --python evaluate.py -- OUTDIR SKETCH [SKETCH ...]

For each SKETCH it reads from OUTDIR:
  SKETCH.obj, SKETCH.rig.json  (rigmesh build: mesh, bones, our weights)
  SKETCH.rigmesh               (rigmesh run of a one-step sketch recipe: the same
                                part with its vertex origins, i.e. which vertices
                                are cylindrical, which the rig JSON does not carry)
  SKETCH.blender.json          (blender_autoweights.py: Blender's normalised weights)
and writes SKETCH.metrics.json (figures and, per moved vertex, details).
"""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cbor_min  # noqa: E402
import limb_metrics as lm  # noqa: E402


def read_obj(path):
    vs, fs = [], []
    for line in open(path):
        p = line.split()
        if p and p[0] == "v":
            vs.append([float(x) for x in p[1:4]])
        elif p and p[0] == "f":
            fs.append([int(x.split("/")[0]) - 1 for x in p[1:]])
    return np.array(vs), np.array(fs, dtype=np.int64)


def evaluate(outdir, sketch):
    rig = json.load(open(os.path.join(outdir, sketch + ".rig.json")))
    doc = cbor_min.loads(open(os.path.join(outdir, sketch + ".rigmesh"), "rb").read())
    blender = json.load(open(os.path.join(outdir, sketch + ".blender.json")))
    obj_v, obj_f = read_obj(os.path.join(outdir, sketch + ".obj"))
    part = doc["parts"][0]["part"]

    # The document's part is the rig JSON's part: same vertices, faces, bones, weights.
    doc_v = np.array(part["mesh"]["vertices"], dtype=float).reshape(-1, 3)
    doc_f = np.array(part["mesh"]["faces"], dtype=np.int64).reshape(-1, 3)
    rig_v = np.array(rig["vertices"], dtype=float)
    assert doc_v.shape == rig_v.shape == obj_v.shape, "vertex counts differ"
    checks = {
        "rig_vs_document_vertices": float(np.abs(doc_v - rig_v).max()),
        "obj_vs_document_vertices": float(np.abs(doc_v - obj_v).max()),
        "obj_faces_equal_document_faces": bool(np.array_equal(doc_f, obj_f)),
    }
    assert checks["rig_vs_document_vertices"] < 1e-9 and checks["obj_vs_document_vertices"] < 1e-6
    assert checks["obj_faces_equal_document_faces"]

    sk_doc = part["skeleton"]
    jpos = np.array(sk_doc["joints"]["positions"], dtype=float).reshape(-1, 3)
    joints = list(zip(sk_doc["joints"]["ids"], jpos))
    bones = list(zip(sk_doc["bones"]["ids"], sk_doc["bones"]["heads"], sk_doc["bones"]["tails"]))
    assert [b["id"] for b in rig["bones"]] == [b[0] for b in bones], "bone order"
    joint_ids = sk_doc["joints"]["ids"]  # the rig JSON names joints by place in this list
    assert [j["id"] for j in rig["joints"]] == joint_ids
    assert joint_ids[rig["root"]] == sk_doc["root"]
    for b, (i, h, t) in zip(rig["bones"], bones):
        assert (joint_ids[b["head"]], joint_ids[b["tail"]]) == (h, t)
        if b["parent"] >= 0:  # "parent" is a bone index
            assert rig["bones"][b["parent"]]["tail"] == b["head"]
    for j, p in zip(rig["joints"], jpos):
        assert max(abs(x - y) for x, y in zip(j["position"], p)) < 1e-12
    sk = lm.Skeleton(joints, bones, sk_doc["root"])
    index_of_id = {i: k for k, (i, _h, _t) in enumerate(bones)}

    ours = [[(int(b), float(w)) for b, w in ws] for ws in rig["weights"]]
    ours_doc = []
    for flat in part["weights"]["byBoneId"]:
        ours_doc.append([(index_of_id[flat[k]], float(flat[k + 1])) for k in range(0, len(flat), 2)])
    W1, W2 = lm.dense(ours, len(bones)), lm.dense(ours_doc, len(bones))
    checks["rig_vs_document_weights"] = float(np.abs(W1 - W2).max())
    theirs = [[(int(b), float(w)) for b, w in ws] for ws in blender["weights"]]

    cylindrical = [k == 0 for k in part["origins"]["kind"]]  # RegionKind::Cylindrical == 0
    closest, without_visible = lm.closest_visible_bones(doc_v, doc_f, sk.segments())

    out = {"sketch": sketch, "vertices": len(doc_v), "faces": len(doc_f), "bones": len(bones),
           "limbs": [dict(l, base=int(l["base"])) for l in lm.limbs_of(sk)],
           "cylindrical_vertices": int(sum(cylindrical)),
           "vertices_without_visible_bone": without_visible, "checks": checks,
           "blender_unweighted_vertices": blender["unweighted_vertices"],
           "blender_bones_without_weight": blender["bones_without_weight"]}
    limbs = lm.limbs_of(sk)
    lov = lm.limb_of_vertex(sk, limbs, closest, cylindrical)
    out["limb_vertices"] = [int((lov == l).sum()) for l in range(len(limbs))]
    out["nearest_visible_bone"] = lm.nearest_visible_bone(closest)
    for name, weights in (("ours", ours), ("blender", theirs)):
        details = []
        jumps = []
        out[name] = {
            "leak": lm.limb_leak(doc_v, sk, weights, closest, cylindrical, details),
            "smoothness_p99": lm.largest_bone_jump_p99(doc_f, weights, len(bones), jumps),
            "dominant_closest_visible": lm.dominant_is_closest_visible_rate(weights, closest),
            "moved": details,
        }
        e, j = jumps[0]
        out[name]["edges_above_p99"] = int((j > out[name]["smoothness_p99"]).sum())
        out[name]["max_jump"] = float(j.max()) if len(j) else 0.0
    json.dump(out, open(os.path.join(outdir, sketch + ".metrics.json"), "w"))
    print("METRICS %s ours leak %d p99 %.6g dom %.6g | blender leak %d p99 %.6g dom %.6g" %
          (sketch, out["ours"]["leak"], out["ours"]["smoothness_p99"],
           out["ours"]["dominant_closest_visible"], out["blender"]["leak"],
           out["blender"]["smoothness_p99"], out["blender"]["dominant_closest_visible"]))
    return out


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:]
    for s in argv[1:]:
        evaluate(argv[0], s)
