// A block of vertices for dual quaternion skinning (pose/SkinningKernel.h):
// their blended dual quaternions and rest positions and normals, laid out by
// coordinate so that several vertices are finished at once, and the
// finishing itself (pose/SkinningLanes.h). Includes nothing: it is also
// compiled with AVX (pose/SkinningKernelAvx.cpp), where any inline function
// it brought along could be the copy the linker keeps for every caller.
#pragma once

namespace rigmesh::skinning {

struct DualQuaternionBlock {
    static constexpr int kSize = 64;
    alignas(64) double real[4][kSize];  // (x, y, z, w) by coordinate
    alignas(64) double dual[4][kSize];
    alignas(64) double x[3][kSize];
    alignas(64) double n[3][kSize];
};

// Lanes [0, count) of `block`: each blend b = (q0, qe) with |q0| > 0 becomes
// the unit dual quaternion b / |q0|, x its rigid transform of x and n the
// rotated n divided by its length (unless that is 0); a lane with |q0| = 0
// (or NaN) keeps x and n. Normals are left alone unless `normals`. Lanes from
// count up to the next multiple of 4 are overwritten with zeros first. Uses
// AVX where the processor has it; the result is the same bits either way.
void finishDualQuaternions(DualQuaternionBlock& block, int count, bool normals);

// The AVX lanes (pose/SkinningKernelAvx.cpp), for a count that is a
// multiple of 4; only where the build has them and the processor runs them.
void finishDualQuaternionsAvx(DualQuaternionBlock& block, int count, bool normals);

}  // namespace rigmesh::skinning
