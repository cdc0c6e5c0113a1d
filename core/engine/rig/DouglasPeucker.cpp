#include "rig/DouglasPeucker.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>
#include <utility>

#include "base/Error.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {

namespace {

Vec2 perpendicular(const Vec2& v) {
    return {-v.y(), v.x()};
}

void checkThreshold(double threshold) {
    if (!std::isfinite(threshold) || threshold < 0.0) {
        throw std::logic_error(
            "The simplification threshold must be a finite length of at least zero.");
    }
}

// The shared divide and conquer. error(i, j, k) is the error of sample k
// against the range [i, j]; a range splits when its largest error exceeds
// limit. An explicit stack keeps long axes off the call stack.
std::vector<int> simplify(int count, double limit,
                          const std::function<double(int, int, int)>& error) {
    if (count <= 0) {
        return {};
    }
    if (count == 1) {
        return {0};
    }
    std::vector<int> kept{0, count - 1};
    std::vector<std::pair<int, int>> ranges{{0, count - 1}};
    while (!ranges.empty()) {
        const auto [i, j] = ranges.back();
        ranges.pop_back();
        int worst = -1;
        double worstError = limit;
        for (int k = i + 1; k < j; ++k) {
            const double e = error(i, j, k);
            if (e > worstError) {
                worst = k;
                worstError = e;
            }
        }
        if (worst >= 0) {
            kept.push_back(worst);
            ranges.push_back({worst, j});
            ranges.push_back({i, worst});
        }
    }
    std::sort(kept.begin(), kept.end());
    return kept;
}

}  // namespace

std::vector<int> douglasPeucker(const std::vector<AxisSample>& axis, double threshold) {
    checkThreshold(threshold);
    return simplify(static_cast<int>(axis.size()), threshold, [&](int i, int j, int k) {
        return distanceToSegment(axis[k].point, axis[i].point, axis[j].point);
    });
}

CdpTrapezoid cdpTrapezoid(const AxisSample& first, const AxisSample& last) {
    Vec2 u = last.point - first.point;
    if (u.squaredNorm() == 0.0) {
        u = perpendicular(first.chordB - first.chordA);
    }
    u = u.squaredNorm() > 0.0 ? u.normalized() : Vec2(1.0, 0.0);
    const Vec2 n = perpendicular(u);
    // Paper 2.3: the bases are the end chords projected onto the normal of v_i v_j.
    const double hFirst = std::abs((first.chordA - first.chordB).dot(n)) / 2.0;
    const double hLast = std::abs((last.chordA - last.chordB).dot(n)) / 2.0;
    return {first.point + hFirst * n, first.point - hFirst * n, last.point - hLast * n,
            last.point + hLast * n, n};
}

double cdpError(const CdpTrapezoid& trapezoid, const AxisSample& sample) {
    const bool aIsUpper =
        sample.chordA.dot(trapezoid.normal) >= sample.chordB.dot(trapezoid.normal);
    const Vec2& upper = aIsUpper ? sample.chordA : sample.chordB;
    const Vec2& lower = aIsUpper ? sample.chordB : sample.chordA;
    const double e1 = distanceToSegment(upper, trapezoid.a, trapezoid.d);
    const double e2 = distanceToSegment(lower, trapezoid.b, trapezoid.c);
    return e1 * e1 + e2 * e2;
}

std::vector<int> cylindricalDouglasPeucker(const std::vector<AxisSample>& axis, double threshold) {
    checkThreshold(threshold);
    // The trapezoid depends only on the range: cache it for the current one.
    int cachedI = -1;
    int cachedJ = -1;
    CdpTrapezoid trapezoid{};
    return simplify(static_cast<int>(axis.size()), threshold * threshold, [&](int i, int j, int k) {
        if (i != cachedI || j != cachedJ) {
            trapezoid = cdpTrapezoid(axis[i], axis[j]);
            cachedI = i;
            cachedJ = j;
        }
        return cdpError(trapezoid, axis[k]);
    });
}

std::vector<int> cylindricalDouglasPeuckerInSpace(const std::vector<TubeSample>& tube,
                                                  double threshold) {
    checkThreshold(threshold);
    return simplify(static_cast<int>(tube.size()), threshold * threshold, [&](int i, int j, int k) {
        const Vec3 ab = tube[j].point - tube[i].point;
        const double lengthSquared = ab.squaredNorm();
        const double t =
            lengthSquared == 0.0
                ? 0.0
                : std::clamp((tube[k].point - tube[i].point).dot(ab) / lengthSquared, 0.0, 1.0);
        const double d = (tube[k].point - (tube[i].point + t * ab)).norm();
        const double dr = tube[k].radius - ((1.0 - t) * tube[i].radius + t * tube[j].radius);
        return 2.0 * (d * d + dr * dr);
    });
}

}  // namespace rigmesh
