// Rounding an outline's concave corners: a concave corner
// sharper than an arc of the given radius becomes about that arc, convex
// corners and straight runs stay where they are, and the area only grows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "sketch/ConcaveCorners.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

// The signed turn at each vertex of a closed polygon (negative: concave when
// counter-clockwise).
std::vector<double> turns(const Polyline2& polygon) {
    const std::size_t n = polygon.size();
    std::vector<double> result;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 in = polygon[i] - polygon[(i + n - 1) % n];
        const Vec2 out = polygon[(i + 1) % n] - polygon[i];
        result.push_back(std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out)));
    }
    return result;
}

// A counter-clockwise L (a 90-degree concave corner at (1, 1)), sampled
// every `h` along its edges.
Polyline2 lShape(double h) {
    const Polyline2 corners{{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 3}, {0, 3}};
    double length = polylineLength(corners, true);
    return resampleClosed(corners, static_cast<std::size_t>(std::lround(length / h)));
}

TEST(ConcaveCorners, AConcaveRightAngleBecomesAnArcOfAboutTheRadius) {
    constexpr double h = 0.1;
    const Polyline2 outline = lShape(h);
    const Polyline2 rounded = resampleClosed(roundConcaveCorners(outline, 1.5 * h), outline.size());
    const std::vector<double> before = turns(outline), after = turns(rounded);
    const double sharpestBefore = *std::min_element(before.begin(), before.end());
    const double sharpestAfter = *std::min_element(after.begin(), after.end());
    EXPECT_LT(sharpestBefore, -1.5);  // the corner turns 90 degrees at one vertex
    // About h / 1.5h per sample (38 degrees), allowing for the resampling.
    EXPECT_GT(sharpestAfter, -1.0 / 1.5 - 0.15);
    EXPECT_GT(signedArea(rounded), signedArea(outline));
    // Filled only near the corner: the apex moves by less than two samples.
    double apexMove = std::numeric_limits<double>::infinity();
    for (const Vec2& p : rounded)
        apexMove = std::min(apexMove, (p - Vec2(1, 1)).norm());
    EXPECT_GT(apexMove, 0.2 * h);
    EXPECT_LT(apexMove, 2.0 * h);
}

TEST(ConcaveCorners, ConvexCornersAndStraightRunsStayPut) {
    constexpr double h = 0.1;
    const Polyline2 outline = lShape(h);
    const Polyline2 rounded = roundConcaveCorners(outline, 1.5 * h);
    ASSERT_EQ(rounded.size(), outline.size());
    int moved = 0;
    for (std::size_t i = 0; i < outline.size(); ++i) {
        if ((rounded[i] - outline[i]).norm() > 1e-12) {
            ++moved;
            // Only points near the concave corner move.
            EXPECT_LT((outline[i] - Vec2(1, 1)).norm(), 5 * h) << i;
        }
    }
    EXPECT_GT(moved, 0);
}

TEST(ConcaveCorners, AConvexPolygonIsUnchanged) {
    Polyline2 circle;
    for (int i = 0; i < 12; ++i) {
        const double t = 2 * std::numbers::pi * i / 12;
        circle.emplace_back(std::cos(t), std::sin(t));
    }
    const Polyline2 square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    EXPECT_EQ(roundConcaveCorners(circle, 10.0), circle);
    EXPECT_EQ(roundConcaveCorners(square, 10.0), square);
}

TEST(ConcaveCorners, AZeroRadiusKeepsEveryCorner) {
    const Polyline2 outline = lShape(0.1);
    EXPECT_EQ(roundConcaveCorners(outline, 0.0), outline);
}

}  // namespace
}  // namespace rigmesh
