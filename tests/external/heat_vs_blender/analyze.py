"""Where our leak exceeds Blender's: per sketch, the moved vertices of other
limbs by (turned limb -> vertex's limb), their distance from the turned limb's
base joint, and the weight they carry on the turned limb, ours vs Blender.
  blender -b --factory-startup --python analyze.py -- OUTDIR SKETCH [SKETCH ...]
(needs the files run_all.sh leaves in OUTDIR)."""
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cbor_min  # noqa: E402
import limb_metrics as lm  # noqa: E402


def pct(a, q):
    return float(np.percentile(a, q)) if len(a) else float("nan")


def analyze(outdir, sketch):
    m = json.load(open(os.path.join(outdir, sketch + ".metrics.json")))
    rig = json.load(open(os.path.join(outdir, sketch + ".rig.json")))
    bl = json.load(open(os.path.join(outdir, sketch + ".blender.json")))
    part = cbor_min.loads(open(os.path.join(outdir, sketch + ".rigmesh"), "rb").read())["parts"][0]["part"]
    V = np.array(rig["vertices"])
    F = np.array(part["mesh"]["faces"], dtype=np.int64).reshape(-1, 3)
    nb = len(rig["bones"])
    Wo = lm.dense(rig["weights"], nb)
    Wb = lm.dense(bl["weights"], nb)
    joints = np.array([j["position"] for j in rig["joints"]])
    jid = [j["id"] for j in rig["joints"]]
    limbs = m["limbs"]
    kind = np.array(part["origins"]["kind"])
    region = np.array(part["origins"]["region"])
    nearest = np.array(m["nearest_visible_bone"])
    print("=" * 100)
    print("%s: ours leak %d, Blender leak %d; limbs: %s" % (
        sketch, m["ours"]["leak"], m["blender"]["leak"],
        "; ".join("L%d base joint %d bones %s length %.3f (%d vertices)" % (
            l, jid.index(limb["base"]), limb["bones"], limb["length"], m["limb_vertices"][l])
            for l, limb in enumerate(limbs))))
    sets = {}
    for who in ("ours", "blender"):
        sets[who] = {(d["turned_limb"], d["axis"], d["vertex"]): d for d in m[who]["moved"]}
    pairs = sorted({(k[0], sets[w][k]["vertex_limb"]) for w in sets for k in sets[w]})
    print("  moved vertices by turned limb -> limb of the vertex (in-plane + out-of-plane):")
    for tl, vl in pairs:
        n = {w: sum(1 for k, d in sets[w].items() if k[0] == tl and d["vertex_limb"] == vl)
             for w in sets}
        print("    L%d -> L%d: ours %4d  blender %4d" % (tl, vl, n["ours"], n["blender"]))
    only_ours = [sets["ours"][k] for k in sets["ours"] if k not in sets["blender"]]
    only_bl = [sets["blender"][k] for k in sets["blender"] if k not in sets["ours"]]
    both = [k for k in sets["ours"] if k in sets["blender"]]
    print("  moved with both weights %d, with ours only %d, with Blender's only %d" %
          (len(both), len(only_ours), len(only_bl)))
    for label, group in (("ours only", only_ours), ("Blender only", only_bl)):
        if not group:
            continue
        dist, wo, wb, far, rg = [], [], [], [], []
        for d in group:
            limb = limbs[d["turned_limb"]]
            base = joints[jid.index(limb["base"])]
            v = d["vertex"]
            # Distance from the turned limb's base joint, relative to the limb's length.
            dist.append(np.linalg.norm(V[v] - base) / limb["length"])
            wo.append(Wo[v, limb["bones"]].sum())
            wb.append(Wb[v, limb["bones"]].sum())
            # Along the vertex's own limb: how far past the base joint (bone parameter).
            rg.append(region[v])
        dist, wo, wb = map(np.array, (dist, wo, wb))
        print("    %s: distance from the turned limb's base / its length: median %.3f, 90%% %.3f, max %.3f"
              % (label, pct(dist, 50), pct(dist, 90), dist.max()))
        print("      weight on the turned limb: ours median %.4f (10%% %.4f, 90%% %.4f); Blender's median %.4f "
              "(10%% %.4f, 90%% %.4f); Blender's weight exactly 0 at %d of %d" %
              (pct(wo, 50), pct(wo, 10), pct(wo, 90), pct(wb, 50), pct(wb, 10), pct(wb, 90),
               int((wb == 0).sum()), len(wb)))
        hist = np.histogram(dist, bins=[0, 0.1, 0.2, 0.3, 0.5, 1.0, 10])[0]
        print("      by distance/length [0,.1,.2,.3,.5,1,+]: %s" % list(hist))
    # The tail: vertices of other limbs with a small but non-zero weight on a limb.
    lov = np.full(len(V), -1)
    for v in range(len(V)):
        n = nearest[v]
        if n >= 0 and kind[v] == 0:
            for l, limb in enumerate(limbs):
                if n in limb["bones"]:
                    lov[v] = l
    for who, W in (("ours", Wo), ("blender", Wb)):
        counts = {t: 0 for t in (1e-4, 0.01, 0.025, 0.05, 0.1, 0.25)}
        for l, limb in enumerate(limbs):
            wl = W[:, limb["bones"]].sum(axis=1)
            other = (lov >= 0) & (lov != l)
            for t in counts:
                counts[t] += int((other & (wl > t)).sum())
        print("  %-7s (limb, vertex of another limb) pairs with weight on the limb > t: %s" % (
            who, ", ".join("%g: %d" % (t, c) for t, c in counts.items())))


if __name__ == "__main__":
    argv = sys.argv[sys.argv.index("--") + 1:]
    for s in argv[1:]:
        analyze(argv[0], s)
