// The AVX lanes of dual quaternion skinning (pose/SkinningLanes.h), four
// vertices at a time. core/engine/CMakeLists.txt compiles this file alone
// with -mavx (no FMA: a fused multiply-add rounds once where the plain
// formulation rounds twice) on x86-64; pose/SkinningKernel.cpp calls it only
// where the processor runs AVX. It includes nothing but the intrinsics and
// headers without inline code (pose/DualQuaternionBlock.h), so no function
// compiled here for AVX can stand in for another file's copy.
#if defined(__AVX__)

#include <immintrin.h>

#include "pose/SkinningLanes.h"

namespace rigmesh::skinning {

namespace {

// Four doubles; a mask is all ones or all zeros per lane.
struct Lanes {
    static constexpr int kWidth = 4;
    __m256d v;
    static Lanes load(const double* p) { return {_mm256_load_pd(p)}; }
    static Lanes all(double x) { return {_mm256_set1_pd(x)}; }
    void store(double* p) const { _mm256_store_pd(p, v); }
};
inline Lanes operator+(Lanes a, Lanes b) {
    return {_mm256_add_pd(a.v, b.v)};
}
inline Lanes operator-(Lanes a, Lanes b) {
    return {_mm256_sub_pd(a.v, b.v)};
}
inline Lanes operator*(Lanes a, Lanes b) {
    return {_mm256_mul_pd(a.v, b.v)};
}
inline Lanes operator/(Lanes a, Lanes b) {
    return {_mm256_div_pd(a.v, b.v)};
}
inline Lanes squareRoot(Lanes a) {
    return {_mm256_sqrt_pd(a.v)};
}
inline Lanes positive(Lanes a) {
    return {_mm256_cmp_pd(a.v, _mm256_setzero_pd(), _CMP_GT_OQ)};
}
inline Lanes select(Lanes mask, Lanes a, Lanes b) {
    return {_mm256_blendv_pd(b.v, a.v, mask.v)};
}

}  // namespace

void finishDualQuaternionsAvx(DualQuaternionBlock& block, int count, bool normals) {
    finishLanes<Lanes>(block, count, normals);
}

}  // namespace rigmesh::skinning

#endif
