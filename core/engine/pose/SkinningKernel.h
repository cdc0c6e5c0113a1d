// The per-vertex arithmetic of skinning (pose/Skinning.h), shared by the
// path over a part's weight lists (pose/Skinning.cpp) and the one over a
// SkinningBinding (pose/SkinningBinding.cpp) so that both give the same bits.
// Internal to those two files.
//
// The arithmetic is that of the plain Eigen formulation (per vertex: the
// blended dual quaternion divided by its norm, Eigen's toRotationMatrix, the
// translation 2 (w0 ve - we v0 + v0 x ve), the normal rotated and divided by
// its length), operation for operation and in the same order, so that saved
// documents deform to the same bits as before (tests/model/
// LegacyDocumentTest.cpp compares a posed OBJ byte for byte). Eigen's 4-vector
// dot product and norm sum as (x0 y0 + x2 y2) + (x1 y1 + x3 y3) (two lanes of
// SSE2 added, then the lanes), and so do these kernels. The speed comes from
// elsewhere: the vertices are blended one by one into a block of
// DualQuaternionBlock::kSize, laid out by coordinate, and the block's
// normalisation and transforms run on several vertices at once
// (pose/SkinningLanes.h: 4 with AVX, 2 with SSE2), which changes no result:
// every lane does the same IEEE operations a scalar would, and no
// multiply-add is fused.
//
// `Table` holds the per-bone data of one pose, indexed as the influences name
// bones: real(i) and dual(i) point to a unit dual quaternion's (x, y, z, w)
// coefficients, matrix(i) to a 3x3 rotation (column-major, as Eigen stores
// it), translation(i) to 3 doubles, identity(i) is true for exactly the
// identity transform. `Source` holds the influences:
// source.forEach(v, f) calls f(bone index, weight) for vertex v's influences
// in their order, source.empty(v) is true if it has none, source.pivot(v) is
// the index of its dominant bone (the first of its largest weights; only
// asked of a vertex with influences).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "base/Types.h"
#include "pose/DualQuaternionBlock.h"
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
// renormalised (the blended matrix is not a rotation). A vertex without
// influences, or whose bones all have the identity transform, is copied.
template <class Table, class Source>
inline void linearBlendVertex(const Table& t, const Source& source, int v, const Vec3& x,
                              const Vec3* n, Vec3& xOut, Vec3* nOut) {
    double m[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
    double tr[3] = {0, 0, 0};
    bool identity = true;
    source.forEach(v, [&](std::size_t bone, double weight) {
        identity = identity && t.identity(bone);
        const double* r = t.matrix(bone);
        const double* b = t.translation(bone);
        for (int i = 0; i < 9; ++i)
            m[i] += weight * r[i];
        for (int i = 0; i < 3; ++i)
            tr[i] += weight * b[i];
    });
    if (identity) {
        xOut = x;
        if (n)
            *nOut = *n;
        return;
    }
    xOut = Vec3(m[0] * x[0] + m[3] * x[1] + m[6] * x[2] + tr[0],
                m[1] * x[0] + m[4] * x[1] + m[7] * x[2] + tr[1],
                m[2] * x[0] + m[5] * x[1] + m[8] * x[2] + tr[2]);
    if (n) {
        const Vec3& w = *n;
        *nOut = normalisedOr(m[0] * w[0] + m[3] * w[1] + m[6] * w[2],
                             m[1] * w[0] + m[4] * w[1] + m[7] * w[2],
                             m[2] * w[0] + m[5] * w[1] + m[8] * w[2], w);
    }
}

// Vertex v's blend into lane `lane` of `block`: every bone's quaternion
// flipped into the hemisphere of the dominant bone's (the antipodal fix,
// Kavan et al. 2008 section 4), then summed with the weights (DLB, section
// 3.4). A vertex without influences or whose bones all have exactly the
// identity transform gets a zero real part, which finishDualQuaternions
// leaves at rest: the rest pose returns the rest mesh bit for bit.
template <class Table, class Source>
inline void blendDualQuaternion(const Table& t, const Source& source, int v,
                                DualQuaternionBlock& block, int lane) {
    if (source.empty(v)) {
        for (int i = 0; i < 4; ++i)
            block.real[i][lane] = block.dual[i][lane] = 0;
        return;
    }
    const double* p = t.real(source.pivot(v));
    bool identity = true;
#if defined(__SSE2__)
    const __m128d p01 = _mm_loadu_pd(p), p23 = _mm_loadu_pd(p + 2);
    __m128d r01 = _mm_setzero_pd(), r23 = _mm_setzero_pd();
    __m128d d01 = _mm_setzero_pd(), d23 = _mm_setzero_pd();
    source.forEach(v, [&](std::size_t bone, double weight) {
        identity = identity && t.identity(bone);
        const double* r = t.real(bone);
        const double* d = t.dual(bone);
        const __m128d q01 = _mm_loadu_pd(r), q23 = _mm_loadu_pd(r + 2);
        // Eigen's dot: (r0 p0 + r2 p2) + (r1 p1 + r3 p3).
        const __m128d half = _mm_add_pd(_mm_mul_pd(q01, p01), _mm_mul_pd(q23, p23));
        const double dot = _mm_cvtsd_f64(_mm_add_sd(half, _mm_unpackhi_pd(half, half)));
        const __m128d w = _mm_set1_pd(dot < 0 ? -weight : weight);
        r01 = _mm_add_pd(r01, _mm_mul_pd(w, q01));
        r23 = _mm_add_pd(r23, _mm_mul_pd(w, q23));
        d01 = _mm_add_pd(d01, _mm_mul_pd(w, _mm_loadu_pd(d)));
        d23 = _mm_add_pd(d23, _mm_mul_pd(w, _mm_loadu_pd(d + 2)));
    });
    if (identity)
        r01 = r23 = _mm_setzero_pd();
    _mm_storel_pd(&block.real[0][lane], r01);
    _mm_storeh_pd(&block.real[1][lane], r01);
    _mm_storel_pd(&block.real[2][lane], r23);
    _mm_storeh_pd(&block.real[3][lane], r23);
    _mm_storel_pd(&block.dual[0][lane], d01);
    _mm_storeh_pd(&block.dual[1][lane], d01);
    _mm_storel_pd(&block.dual[2][lane], d23);
    _mm_storeh_pd(&block.dual[3][lane], d23);
#else
    double real[4] = {0, 0, 0, 0}, dual[4] = {0, 0, 0, 0};
    source.forEach(v, [&](std::size_t bone, double weight) {
        identity = identity && t.identity(bone);
        const double* r = t.real(bone);
        const double* d = t.dual(bone);
        const double dot = (r[0] * p[0] + r[2] * p[2]) + (r[1] * p[1] + r[3] * p[3]);
        const double w = dot < 0 ? -weight : weight;
        for (int i = 0; i < 4; ++i) {
            real[i] += w * r[i];
            dual[i] += w * d[i];
        }
    });
    for (int i = 0; i < 4; ++i) {
        block.real[i][lane] = identity ? 0.0 : real[i];
        block.dual[i][lane] = dual[i];
    }
#endif
}

// Vertices [begin, end): positions (and normals, where `restNormals` is not
// null) skinned by dual quaternion blending into `out` (and `outNormals`).
template <class Table, class Source>
void dualQuaternionRange(const Table& t, const Source& source, int begin, int end,
                         const Vec3* restPositions, const Vec3* restNormals, Vec3* out,
                         Vec3* outNormals) {
    DualQuaternionBlock block;
    const bool normals = restNormals != nullptr;
    for (int first = begin; first < end; first += DualQuaternionBlock::kSize) {
        const int count = std::min(DualQuaternionBlock::kSize, end - first);
        for (int lane = 0; lane < count; ++lane) {
            const int v = first + lane;
            blendDualQuaternion(t, source, v, block, lane);
            for (int i = 0; i < 3; ++i)
                block.x[i][lane] = restPositions[v][i];
            if (normals)
                for (int i = 0; i < 3; ++i)
                    block.n[i][lane] = restNormals[v][i];
        }
        finishDualQuaternions(block, count, normals);
        for (int lane = 0; lane < count; ++lane) {
            const int v = first + lane;
            out[v] = Vec3(block.x[0][lane], block.x[1][lane], block.x[2][lane]);
            if (normals)
                outNormals[v] = Vec3(block.n[0][lane], block.n[1][lane], block.n[2][lane]);
        }
    }
}

// Vertices [begin, end) of `out` (sized already; normals empty when
// `restNormals` is) skinned by `method`.
template <class Table, class Source>
void skinRange(const Table& t, const Source& source, SkinningMethod method, int begin, int end,
               const std::vector<Vec3>& restPositions, const std::vector<Vec3>& restNormals,
               SkinnedVertices& out) {
    const bool normals = !restNormals.empty();
    if (method == SkinningMethod::DualQuaternion) {
        dualQuaternionRange(t, source, begin, end, restPositions.data(),
                            normals ? restNormals.data() : nullptr, out.positions.data(),
                            out.normals.data());
        return;
    }
    for (int v = begin; v < end; ++v)
        linearBlendVertex(t, source, v, restPositions[v], normals ? &restNormals[v] : nullptr,
                          out.positions[v], normals ? &out.normals[v] : nullptr);
}

}  // namespace rigmesh::skinning
