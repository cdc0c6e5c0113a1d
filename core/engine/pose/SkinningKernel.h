// The per-vertex arithmetic of skinning (pose/Skinning.h), shared by the
// path over a part's weight lists (pose/Skinning.cpp) and the one over a
// SkinningBinding (pose/SkinningBinding.cpp) so that both give the same bits.
// Internal to those two files.
//
// `Table` holds the per-bone data of one pose, indexed as the influences name
// bones: real(i) and dual(i) point to a unit dual quaternion's (x, y, z, w)
// coefficients, matrix(i) to a 3x3 rotation (column-major, as Eigen stores it), translation(i) to
// 3 doubles, identity(i) is true for exactly the identity transform.
// `influence(k)` gives the k-th (bone index, weight) of the vertex.
#pragma once

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>

#include "base/Types.h"
#include "pose/Skinning.h"

namespace rigmesh::skinning {

// The checks both skinVertices make before skinning; throws
// std::logic_error.
inline void checkInput(std::size_t lists, std::size_t positions, std::size_t normals, int threads) {
    if (lists != positions)
        throw std::logic_error(
            "Skinning needs one weight list per vertex: " + std::to_string(lists) + " lists for " +
            std::to_string(positions) + " vertices.");
    if (normals != 0 && normals != positions)
        throw std::logic_error("Skinning needs one rest normal per vertex or none.");
    if (threads < 1)
        throw std::logic_error("Skinning needs at least one thread.");
}

// Throws std::logic_error if the transforms' skeleton lacks the bone a
// weight names.
inline void checkBone(const SkinningTransforms& transforms, BoneId bone) {
    if (!transforms.hasBone(bone)) [[unlikely]]
        throw std::logic_error("A skin weight refers to bone " + std::to_string(bone) +
                               ", which the posed skeleton does not have.");
}

inline Vec3 normalisedOr(double x, double y, double z, const Vec3& fallback) {
    const double length = std::sqrt(x * x + y * y + z * z);
    return length > 0 ? Vec3(x / length, y / length, z / length) : fallback;
}

// Linear blend: x' = sum_b w_b (R_b x + t_b), n' = (sum_b w_b R_b) n,
// renormalised (the blended matrix is not a rotation).
template <class Table, class Influence>
inline void linearBlendVertex(const Table& t, int count, const Influence& influence, const Vec3& x,
                              const Vec3* n, Vec3& xOut, Vec3* nOut) {
    double m[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double tr[3] = {0, 0, 0};
    bool identity = true;
    for (int k = 0; k < count; ++k) {
        const auto [bone, weight] = influence(k);
        identity = identity && t.identity(bone);
        const double* r = t.matrix(bone);
        const double* b = t.translation(bone);
        for (int i = 0; i < 9; ++i)
            m[i] += weight * r[i];
        for (int i = 0; i < 3; ++i)
            tr[i] += weight * b[i];
    }
    if (count == 0 || identity) {
        xOut = x;
        if (n)
            *nOut = *n;
        return;
    }
    xOut = Vec3(m[0] * x[0] + m[3] * x[1] + m[6] * x[2] + tr[0],
                m[1] * x[0] + m[4] * x[1] + m[7] * x[2] + tr[1],
                m[2] * x[0] + m[5] * x[1] + m[8] * x[2] + tr[2]);
    if (n) {
        const Vec3& v = *n;
        *nOut = normalisedOr(m[0] * v[0] + m[3] * v[1] + m[6] * v[2],
                             m[1] * v[0] + m[4] * v[1] + m[7] * v[2],
                             m[2] * v[0] + m[5] * v[1] + m[8] * v[2], v);
    }
}

// Dual quaternion blending (DLB, Kavan et al. 2008 section 3.4). Every bone's
// quaternion is first flipped into the hemisphere of `pivot`, the vertex's
// dominant bone (the antipodal fix, section 4). The blend b = (q0, qe) is
// not normalised by dividing it by |q0|: with s = |q0|^2 its rotation is
// I + (2/s) [the quadratic terms of q0] and its translation
// (2/s) (w0 ve - we v0 + v0 x ve), the formulas of the unit dual quaternion
// b / |q0| multiplied out (as Kavan et al.'s GPU code does), which needs one
// division and no square root per vertex. Writing the translation out
// projects a non-orthogonal blended dual part away. The rotation is
// orthonormal to rounding, so the normal keeps its length (unit rest
// normals stay unit) without renormalising.
template <class Table, class Influence>
inline void dualQuaternionVertex(const Table& t, int count, const Influence& influence,
                                 std::size_t pivot, const Vec3& x, const Vec3* n, Vec3& xOut,
                                 Vec3* nOut) {
    if (count == 0) {
        xOut = x;
        if (n)
            *nOut = *n;
        return;
    }
    const double* p = t.real(pivot);
    double r0 = 0, r1 = 0, r2 = 0, r3 = 0, d0 = 0, d1 = 0, d2 = 0, d3 = 0;
    bool identity = true;
    for (int k = 0; k < count; ++k) {
        const auto [bone, weight] = influence(k);
        identity = identity && t.identity(bone);
        const double* r = t.real(bone);
        const double* d = t.dual(bone);
        const double w =
            r[0] * p[0] + r[1] * p[1] + r[2] * p[2] + r[3] * p[3] < 0 ? -weight : weight;
        r0 += w * r[0];
        r1 += w * r[1];
        r2 += w * r[2];
        r3 += w * r[3];
        d0 += w * d[0];
        d1 += w * d[1];
        d2 += w * d[2];
        d3 += w * d[3];
    }
    const double s = r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3;
    if (identity || !(s > 0)) {
        xOut = x;
        if (n)
            *nOut = *n;
        return;
    }
    const double k = 2.0 / s;
    const double kx = k * r0, ky = k * r1, kz = k * r2;
    const double xx = kx * r0, yy = ky * r1, zz = kz * r2;
    const double xy = kx * r1, xz = kx * r2, yz = ky * r2;
    const double wx = kx * r3, wy = ky * r3, wz = kz * r3;
    const double m00 = 1 - (yy + zz), m01 = xy - wz, m02 = xz + wy;
    const double m10 = xy + wz, m11 = 1 - (xx + zz), m12 = yz - wx;
    const double m20 = xz - wy, m21 = yz + wx, m22 = 1 - (xx + yy);
    const double t0 = k * (r3 * d0 - d3 * r0 + (r1 * d2 - r2 * d1));
    const double t1 = k * (r3 * d1 - d3 * r1 + (r2 * d0 - r0 * d2));
    const double t2 = k * (r3 * d2 - d3 * r2 + (r0 * d1 - r1 * d0));
    xOut =
        Vec3(m00 * x[0] + m01 * x[1] + m02 * x[2] + t0, m10 * x[0] + m11 * x[1] + m12 * x[2] + t1,
             m20 * x[0] + m21 * x[1] + m22 * x[2] + t2);
    if (n) {
        const Vec3& v = *n;
        *nOut = Vec3(m00 * v[0] + m01 * v[1] + m02 * v[2], m10 * v[0] + m11 * v[1] + m12 * v[2],
                     m20 * v[0] + m21 * v[1] + m22 * v[2]);
    }
}

}  // namespace rigmesh::skinning
