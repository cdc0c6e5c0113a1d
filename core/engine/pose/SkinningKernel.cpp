#include "pose/SkinningKernel.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "pose/SkinningLanes.h"

namespace rigmesh::skinning {

namespace {

#if defined(__SSE2__)
// Two doubles; a mask is all ones or all zeros per lane.
struct Lanes {
    static constexpr int kWidth = 2;
    __m128d v;
    static Lanes load(const double* p) { return {_mm_load_pd(p)}; }
    static Lanes all(double x) { return {_mm_set1_pd(x)}; }
    void store(double* p) const { _mm_store_pd(p, v); }
};
inline Lanes operator+(Lanes a, Lanes b) {
    return {_mm_add_pd(a.v, b.v)};
}
inline Lanes operator-(Lanes a, Lanes b) {
    return {_mm_sub_pd(a.v, b.v)};
}
inline Lanes operator*(Lanes a, Lanes b) {
    return {_mm_mul_pd(a.v, b.v)};
}
inline Lanes operator/(Lanes a, Lanes b) {
    return {_mm_div_pd(a.v, b.v)};
}
inline Lanes squareRoot(Lanes a) {
    return {_mm_sqrt_pd(a.v)};
}
inline Lanes positive(Lanes a) {
    return {_mm_cmpgt_pd(a.v, _mm_setzero_pd())};
}
inline Lanes select(Lanes mask, Lanes a, Lanes b) {
    return {_mm_or_pd(_mm_and_pd(mask.v, a.v), _mm_andnot_pd(mask.v, b.v))};
}
#else
// One double; a mask is 1 or 0.
struct Lanes {
    static constexpr int kWidth = 1;
    double v;
    static Lanes load(const double* p) { return {*p}; }
    static Lanes all(double x) { return {x}; }
    void store(double* p) const { *p = v; }
};
inline Lanes operator+(Lanes a, Lanes b) {
    return {a.v + b.v};
}
inline Lanes operator-(Lanes a, Lanes b) {
    return {a.v - b.v};
}
inline Lanes operator*(Lanes a, Lanes b) {
    return {a.v * b.v};
}
inline Lanes operator/(Lanes a, Lanes b) {
    return {a.v / b.v};
}
inline Lanes squareRoot(Lanes a) {
    return {std::sqrt(a.v)};
}
inline Lanes positive(Lanes a) {
    return {a.v > 0 ? 1.0 : 0.0};
}
inline Lanes select(Lanes mask, Lanes a, Lanes b) {
    return {mask.v != 0 ? a.v : b.v};
}
#endif

// Whether finishDualQuaternionsAvx is built (CMake defines
// RIGMESH_SKINNING_AVX for this file then) and the processor (and system)
// runs AVX.
bool avx() {
#if defined(RIGMESH_SKINNING_AVX)
    static const bool supported = [] {
        __builtin_cpu_init();
        return __builtin_cpu_supports("avx") != 0;
    }();
    return supported;
#else
    return false;
#endif
}

}  // namespace

void finishDualQuaternions(DualQuaternionBlock& block, int count, bool normals) {
    constexpr int kSize = DualQuaternionBlock::kSize;
    // Padding lanes: a zero blend, which stays at rest.
    const int end = std::min(kSize, (count + 3) / 4 * 4);
    for (int lane = count; lane < end; ++lane) {
        for (int i = 0; i < 4; ++i)
            block.real[i][lane] = block.dual[i][lane] = 0;
        for (int i = 0; i < 3; ++i)
            block.x[i][lane] = block.n[i][lane] = 0;
    }
    if (avx())
        finishDualQuaternionsAvx(block, end, normals);
    else
        finishLanes<Lanes>(block, end, normals);
}

}  // namespace rigmesh::skinning
