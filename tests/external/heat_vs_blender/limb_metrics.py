"""The skin weights' figures of merit, ported from tests/engine/part/LimbWeightMetrics.h
and PartTestSupport.h (limbsOf, closestVisibleBones, nearestVisibleBone,
limbLeak, largestBoneJumpP99, dominantIsClosestVisibleRate).

Needs numpy (run inside Blender's Python: blender -b --factory-startup
--python limb_metrics.py -- ...). Used as a module by evaluate.py.
"""
import math

import numpy as np

TIE_TOLERANCE = 1e-2  # parttest::kTieTolerance
START_OFFSET = 1e-6  # BoneVisibility kStartOffset
CONE_COSINE = 0.5  # Pinocchio's vectorInCone


class Skeleton:
    """joints: list of (id, position) in skeleton order; bones: list of
    (id, head joint id, tail joint id) in skeleton order (bone index = position)."""

    def __init__(self, joints, bones, root):
        self.joint_ids = [j for j, _ in joints]
        self.position = {j: np.asarray(p, dtype=float) for j, p in joints}
        self.bones = bones
        self.root = root

    def children_of(self, joint):  # bone indices whose head is `joint`, in bone order
        return [i for i, (_, h, _t) in enumerate(self.bones) if h == joint]

    def degree(self, joint):
        return sum(1 for (_, h, t) in self.bones if h == joint or t == joint)

    def bone_length(self, i):
        _, h, t = self.bones[i]
        return float(np.linalg.norm(self.position[t] - self.position[h]))

    def segments(self):
        return [(self.position[h], self.position[t]) for (_, h, t) in self.bones]


def limbs_of(sk):
    limbs = []
    for j in sk.joint_ids:
        if j != sk.root and sk.degree(j) < 3:
            continue
        for first in sk.children_of(j):
            bones, length, b = [], 0.0, first
            while True:
                bones.append(b)
                length += sk.bone_length(b)
                tail = sk.bones[b][2]
                nxt = sk.children_of(tail)
                if len(nxt) != 1 or sk.degree(tail) != 2:
                    break
                b = nxt[0]
            end = sk.bones[bones[-1]][2]
            if sk.degree(end) == 1:
                limbs.append({"base": j, "bones": bones, "length": length})
    return limbs


def closest_point_on_segment(p, head, tail):
    axis = tail - head
    l2 = float(axis @ axis)
    if not (l2 > 0.0):
        return head.copy()
    t = min(max(float((p - head) @ axis) / l2, 0.0), 1.0)
    return head + t * axis


class Triangles:
    """Segment/triangle crossing tests in double precision (Moller-Trumbore,
    boundaries included, as CGAL's do_intersect counts touching); triangles of
    zero area are left out, as BoneVisibility leaves out degenerate ones."""

    def __init__(self, vertices, faces):
        a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
        keep = np.linalg.norm(np.cross(b - a, c - a), axis=1) > 0.0
        self.a, self.e1, self.e2 = a[keep], (b - a)[keep], (c - a)[keep]
        tri = np.stack([a[keep], b[keep], c[keep]])
        self.lo, self.hi = tri.min(axis=0), tri.max(axis=0)

    def segment_crosses(self, s, e):
        lo, hi = np.minimum(s, e), np.maximum(s, e)
        m = np.all(self.lo <= hi, axis=1) & np.all(self.hi >= lo, axis=1)
        if not m.any():
            return False
        a, e1, e2 = self.a[m], self.e1[m], self.e2[m]
        d = e - s
        p = np.cross(d, e2)
        det = np.einsum("ij,ij->i", e1, p)
        ok = np.abs(det) > 1e-300
        inv = np.where(ok, 1.0 / np.where(ok, det, 1.0), 0.0)
        tv = s - a
        u = np.einsum("ij,ij->i", tv, p) * inv
        q = np.cross(tv, e1)
        v = (q @ d) * inv
        t = np.einsum("ij,ij->i", e2, q) * inv
        hit = ok & (u >= 0) & (v >= 0) & (u + v <= 1) & (t >= 0) & (t <= 1)
        return bool(hit.any())


def vertex_normals(vertices, faces):
    a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
    n = np.cross(b - a, c - a)
    normals = np.zeros_like(vertices)
    for k in range(3):
        np.add.at(normals, faces[:, k], n)
    length = np.linalg.norm(normals, axis=1, keepdims=True)
    return normals / np.where(length > 0, length, 1.0)


def closest_visible_bones(vertices, faces, segments):
    """closestVisibleBones on every vertex: [(bone index, distance), ...] per vertex."""
    tris = Triangles(vertices, faces)
    normals = vertex_normals(vertices, faces)
    result, without_visible = [], 0
    for v, x in enumerate(vertices):
        by_distance = []
        for b, (h, t) in enumerate(segments):
            p = closest_point_on_segment(x, h, t)
            by_distance.append((float(np.linalg.norm(x - p)), b, p))
        by_distance.sort(key=lambda e: (e[0], e[1]))
        chosen = []
        for d, b, p in by_distance:
            if chosen and d > chosen[0][1] * (1.0 + TIE_TOLERANCE):
                break
            outward = x - p
            norm = float(np.linalg.norm(outward))
            in_cone = norm == 0.0 or float(outward @ normals[v]) > CONE_COSINE * norm
            if in_cone:
                start = x + START_OFFSET * (p - x)
                inside = bool(np.all(start == p)) or not tris.segment_crosses(start, p)
                if inside:
                    chosen.append((b, d))
        if not chosen:
            without_visible += 1
            nearest = by_distance[0][0]
            for d, b, _p in by_distance:
                if d > nearest * (1.0 + TIE_TOLERANCE):
                    break
                chosen.append((b, d))
        result.append(chosen)
    return result, without_visible


def nearest_visible_bone(closest):
    out = []
    for entries in closest:
        best, bone = math.inf, -1
        for b, d in entries:
            if d < best:
                best, bone = d, b
        out.append(bone)
    return out


def rotation_matrix(axis, angle):
    axis = axis / np.linalg.norm(axis)
    x, y, z = axis
    c, s = math.cos(angle), math.sin(angle)
    C = 1 - c
    return np.array([[c + x * x * C, x * y * C - z * s, x * z * C + y * s],
                     [y * x * C + z * s, c + y * y * C, y * z * C - x * s],
                     [z * x * C - y * s, z * y * C + x * s, c + z * z * C]])


def dense(weights, bone_count):
    W = np.zeros((len(weights), bone_count))
    for v, ws in enumerate(weights):
        for b, w in ws:
            W[v, b] += w
    return W


def limb_of_vertex(sk, limbs, closest, cylindrical):
    limb_of_bone = [-1] * len(sk.bones)
    for l, limb in enumerate(limbs):
        for b in limb["bones"]:
            limb_of_bone[b] = l
    nearest = nearest_visible_bone(closest)
    return np.array([limb_of_bone[n] if (n >= 0 and cylindrical[v]) else -1
                     for v, n in enumerate(nearest)])


def limb_leak(vertices, sk, weights, closest, cylindrical, details=None):
    """The leak figure; `weights` per vertex [(bone index, weight)], summing to 1
    or empty. If `details` is a list, one record per moved vertex is appended."""
    limbs = limbs_of(sk)
    lov = limb_of_vertex(sk, limbs, closest, cylindrical)
    W = dense(weights, len(sk.bones))
    has = np.array([len(ws) > 0 for ws in weights])
    total = W.sum(axis=1)
    moved = 0
    for l, limb in enumerate(limbs):
        base = sk.position[limb["base"]]
        last_tail = sk.position[sk.bones[limb["bones"][-1]][2]]
        direction = last_tail - base
        direction[2] = 0.0
        direction /= np.linalg.norm(direction)
        in_plane = np.array([0.0, 0.0, 1.0])
        out_of_plane = np.cross(in_plane, direction)
        out_of_plane /= np.linalg.norm(out_of_plane)
        # Limb bones of each vertex that carry an influence (zero weights count, as in C++).
        in_limb = np.zeros(len(vertices), dtype=bool)
        for v, ws in enumerate(weights):
            in_limb[v] = any(b in limb["bones"] for b, _ in ws)
        w_limb = W[:, limb["bones"]].sum(axis=1)
        for name, axis in (("in-plane", in_plane), ("out-of-plane", out_of_plane)):
            R = rotation_matrix(axis, math.pi / 3.0)
            turned = (vertices - base) @ R.T + base
            posed = (total - w_limb)[:, None] * vertices + w_limb[:, None] * turned
            posed = np.where((has & in_limb)[:, None], posed, vertices)
            shift = np.linalg.norm(posed - vertices, axis=1)
            hit = (lov >= 0) & (lov != l) & (shift > 0.01 * limb["length"])
            moved += int(hit.sum())
            if details is not None:
                for v in np.nonzero(hit)[0]:
                    details.append({"turned_limb": l, "axis": name, "vertex": int(v),
                                    "vertex_limb": int(lov[v]), "weight_on_turned": float(w_limb[v]),
                                    "shift_rel": float(shift[v] / limb["length"])})
    return moved


def mesh_edges(faces):
    e = np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]])
    e = np.sort(e, axis=1)
    return np.unique(e, axis=0)


def percentile(values, fraction):
    if len(values) == 0:
        return 0.0
    values = np.sort(values)
    rank = int(fraction * (len(values) - 1))
    return float(values[min(rank, len(values) - 1)])


def largest_bone_jump_p99(faces, weights, bone_count, jumps_out=None):
    W = dense(weights, bone_count)
    e = mesh_edges(faces)
    jumps = np.abs(W[e[:, 0]] - W[e[:, 1]]).max(axis=1) if bone_count else np.zeros(len(e))
    if jumps_out is not None:
        jumps_out.append((e, jumps))
    return percentile(jumps, 0.99)


def dominant_bone(ws):
    best, best_w = -1, -1.0
    for b, w in ws:
        if w > best_w:
            best, best_w = b, w
    return best


def dominant_is_closest_visible_rate(weights, closest):
    hits = sum(1 for ws, c in zip(weights, closest) if dominant_bone(ws) in [b for b, _ in c])
    return hits / len(closest) if closest else 0.0
