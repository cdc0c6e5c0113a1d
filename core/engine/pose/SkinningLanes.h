// The finishing of a DualQuaternionBlock (pose/DualQuaternionBlock.h) over
// lanes of `L` doubles at a time, for pose/SkinningKernel.cpp (SSE2, or one
// double) and pose/SkinningKernelAvx.cpp (AVX). `L` has load(p), all(x),
// store(p), + - * /, and squareRoot(a), positive(a) (a mask, a > 0, false
// for NaN) and select(mask, a, b), found by argument-dependent lookup. Every
// lane does what the plain Eigen formulation did per vertex, in the same
// order (pose/SkinningKernel.h), so every width gives the same bits.
// Includes nothing else, as DualQuaternionBlock.h.
#pragma once

#include "pose/DualQuaternionBlock.h"

namespace rigmesh::skinning {

// Lanes [0, end), end a multiple of L::kWidth.
template <class L>
inline void finishLanes(DualQuaternionBlock& b, int end, bool normals) {
    const L zero = L::all(0), one = L::all(1), two = L::all(2);
    for (int lane = 0; lane < end; lane += L::kWidth) {
        L r0 = L::load(&b.real[0][lane]), r1 = L::load(&b.real[1][lane]);
        L r2 = L::load(&b.real[2][lane]), r3 = L::load(&b.real[3][lane]);
        L d0 = L::load(&b.dual[0][lane]), d1 = L::load(&b.dual[1][lane]);
        L d2 = L::load(&b.dual[2][lane]), d3 = L::load(&b.dual[3][lane]);
        // Eigen's norm of a 4-vector; a lane without a norm stays at rest
        // (and divides by 1 instead, so that no lane divides by 0).
        const L norm = squareRoot((r0 * r0 + r2 * r2) + (r1 * r1 + r3 * r3));
        const L moves = positive(norm);
        const L divisor = select(moves, norm, one);
        r0 = r0 / divisor;
        r1 = r1 / divisor;
        r2 = r2 / divisor;
        r3 = r3 / divisor;
        d0 = d0 / divisor;
        d1 = d1 / divisor;
        d2 = d2 / divisor;
        d3 = d3 / divisor;
        // Eigen's Quaternion::toRotationMatrix with (x, y, z, w) = r.
        const L tx = two * r0, ty = two * r1, tz = two * r2;
        const L twx = tx * r3, twy = ty * r3, twz = tz * r3;
        const L txx = tx * r0, txy = ty * r0, txz = tz * r0;
        const L tyy = ty * r1, tyz = tz * r1, tzz = tz * r2;
        const L m00 = one - (tyy + tzz), m01 = txy - twz, m02 = txz + twy;
        const L m10 = txy + twz, m11 = one - (txx + tzz), m12 = tyz - twx;
        const L m20 = txz - twy, m21 = tyz + twx, m22 = one - (txx + tyy);
        // The translation 2 (w0 ve - we v0 + v0 x ve), with Eigen's cross
        // product: written out, a non-orthogonal blended dual part is
        // projected away.
        const L t0 = two * ((r3 * d0 - d3 * r0) + (r1 * d2 - r2 * d1));
        const L t1 = two * ((r3 * d1 - d3 * r1) + (r2 * d0 - r0 * d2));
        const L t2 = two * ((r3 * d2 - d3 * r2) + (r0 * d1 - r1 * d0));
        const L x0 = L::load(&b.x[0][lane]), x1 = L::load(&b.x[1][lane]);
        const L x2 = L::load(&b.x[2][lane]);
        select(moves, m00 * x0 + m01 * x1 + m02 * x2 + t0, x0).store(&b.x[0][lane]);
        select(moves, m10 * x0 + m11 * x1 + m12 * x2 + t1, x1).store(&b.x[1][lane]);
        select(moves, m20 * x0 + m21 * x1 + m22 * x2 + t2, x2).store(&b.x[2][lane]);
        if (!normals)
            continue;
        const L n0 = L::load(&b.n[0][lane]), n1 = L::load(&b.n[1][lane]);
        const L n2 = L::load(&b.n[2][lane]);
        const L a0 = m00 * n0 + m01 * n1 + m02 * n2;
        const L a1 = m10 * n0 + m11 * n1 + m12 * n2;
        const L a2 = m20 * n0 + m21 * n1 + m22 * n2;
        const L length = squareRoot(a0 * a0 + a1 * a1 + a2 * a2);
        const L scaled = select(moves, positive(length), zero);
        const L by = select(scaled, length, one);
        select(scaled, a0 / by, n0).store(&b.n[0][lane]);
        select(scaled, a1 / by, n1).store(&b.n[1][lane]);
        select(scaled, a2 / by, n2).store(&b.n[2][lane]);
    }
}

}  // namespace rigmesh::skinning
