#include "geometry/CatmullRom.h"

#include <algorithm>
#include <cmath>

namespace rigmesh {

Vec2 centripetalCatmullRom(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3,
                           double fraction) {
    auto knot = [](const Vec2& a, const Vec2& b) {
        return std::max(std::sqrt((b - a).norm()), 1e-12);
    };
    const double t1 = knot(p0, p1), t2 = t1 + knot(p1, p2), t3 = t2 + knot(p2, p3);
    const double t = t1 + (t2 - t1) * fraction;
    // Barry and Goldman's pyramid, with t0 = 0.
    const Vec2 a1 = (t1 - t) / t1 * p0 + t / t1 * p1;
    const Vec2 a2 = (t2 - t) / (t2 - t1) * p1 + (t - t1) / (t2 - t1) * p2;
    const Vec2 a3 = (t3 - t) / (t3 - t2) * p2 + (t - t2) / (t3 - t2) * p3;
    const Vec2 b1 = (t2 - t) / t2 * a1 + t / t2 * a2;
    const Vec2 b2 = (t3 - t) / (t3 - t1) * a2 + (t - t1) / (t3 - t1) * a3;
    return (t2 - t) / (t2 - t1) * b1 + (t - t1) / (t2 - t1) * b2;
}

}  // namespace rigmesh
