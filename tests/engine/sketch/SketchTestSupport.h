// Independent checks of cleaned polygons for the sketch tests: brute-force
// simplicity, orientation and spacing, written without the engine's helpers.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "base/Types.h"
#include "sketch/PolygonGeometry.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {

// True when closed segments ab and cd share a point.
inline bool testSegmentsMeet(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    const auto side = [](const Vec2& o, const Vec2& p, const Vec2& q) {
        const double v = (p - o).x() * (q - o).y() - (p - o).y() * (q - o).x();
        return (v > 0.0) - (v < 0.0);
    };
    const auto within = [](const Vec2& o, const Vec2& p, const Vec2& q) {
        return std::min(o.x(), p.x()) <= q.x() && q.x() <= std::max(o.x(), p.x()) &&
               std::min(o.y(), p.y()) <= q.y() && q.y() <= std::max(o.y(), p.y());
    };
    if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) ||
        std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
        std::max(a.y(), b.y()) < std::min(c.y(), d.y()) ||
        std::max(c.y(), d.y()) < std::min(a.y(), b.y())) {
        return false;
    }
    const int s1 = side(a, b, c), s2 = side(a, b, d), s3 = side(c, d, a), s4 = side(c, d, b);
    if (s1 * s2 < 0 && s3 * s4 < 0) {
        return true;
    }
    return (s1 == 0 && within(a, b, c)) || (s2 == 0 && within(a, b, d)) ||
           (s3 == 0 && within(c, d, a)) || (s4 == 0 && within(c, d, b));
}

// O(n^2) check that no two non-adjacent edges of the closed polygon meet.
inline bool testIsSimple(const std::vector<Vec2>& polygon) {
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) {
                continue;
            }
            if (testSegmentsMeet(polygon[i], polygon[(i + 1) % n], polygon[j],
                                 polygon[(j + 1) % n])) {
                return false;
            }
        }
    }
    return true;
}

inline void expectSimpleCounterClockwise(const std::vector<Vec2>& polygon) {
    ASSERT_GE(polygon.size(), 3u);
    EXPECT_GT(signedArea(polygon), 0.0);
    EXPECT_NE(polygon.front(), polygon.back());
    EXPECT_TRUE(testIsSimple(polygon));
}

// Ratio of the longest to the shortest edge, and the mean edge against the
// reported spacing.
inline void expectUniformSpacing(const CleanPolygon& clean, double maxRatio) {
    const auto& p = clean.points;
    double shortest = INFINITY, longest = 0.0, total = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double length = (p[(i + 1) % p.size()] - p[i]).norm();
        shortest = std::min(shortest, length);
        longest = std::max(longest, length);
        total += length;
    }
    EXPECT_LT(longest / shortest, maxRatio);
    EXPECT_NEAR(total / static_cast<double>(p.size()), clean.spacing, 0.05 * clean.spacing);
}

}  // namespace rigmesh
