// The interior lattice of a connecting patch: the grid of boundary segments
// keeps exactly the points a test against every segment keeps, and every loop
// ends, whatever the boundary's position and the edge length.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "base/Error.h"
#include "surface/PatchLattice.h"

namespace rigmesh {
namespace {

// A star-shaped loop with long and short edges.
std::vector<Vec2> starLoop(const Vec2& centre, double radius) {
    std::vector<Vec2> loop;
    for (int i = 0; i < 40; ++i) {
        const double angle = 2 * std::numbers::pi * i / 40;
        const double r = radius * (i % 2 ? 0.45 : 1.0);
        loop.push_back(centre + r * Vec2(std::cos(angle), std::sin(angle)));
    }
    return loop;
}

double distanceToLoop(const Vec2& p, const std::vector<Vec2>& loop) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < loop.size(); ++i) {
        const Vec2 a = loop[i], ab = loop[(i + 1) % loop.size()] - a;
        const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
        best = std::min(best, (p - (a + t * ab)).norm());
    }
    return best;
}

TEST(PatchLattice, KeepsExactlyThePointsMoreThanHalfAnEdgeFromTheBoundary) {
    const std::vector<Vec2> loop = starLoop(Vec2(3, -2), 5.0);
    const double h = 0.2;
    const std::vector<Vec2> points = latticeInside(loop, h);
    ASSERT_GT(points.size(), 100u);
    for (const Vec2& p : points)
        EXPECT_GT(distanceToLoop(p, loop), 0.5 * h);
    // Every lattice node with that clearance is kept: count them directly.
    Eigen::AlignedBox2d box;
    for (const Vec2& p : loop)
        box.extend(p);
    std::size_t expected = 0;
    const double rowHeight = h * std::sqrt(3.0) / 2;
    for (int row = 0; box.min().y() + (row + 0.5) * rowHeight < box.max().y(); ++row)
        for (int column = 0; box.min().x() + (column + (row % 2 ? 0.5 : 0.0)) * h < box.max().x();
             ++column) {
            const Vec2 p(box.min().x() + (column + (row % 2 ? 0.5 : 0.0)) * h,
                         box.min().y() + (row + 0.5) * rowHeight);
            expected += distanceToLoop(p, loop) > 0.5 * h;
        }
    EXPECT_EQ(points.size(), expected);
}

TEST(PatchLattice, EndsFarFromTheOriginWhereTheEdgeIsBelowTheCoordinateStep) {
    // At 1e15 doubles are 0.125 apart; an edge of 0.01 cannot advance x += h.
    // The loop is 2 across: at most one point per lattice node, (2 / h + 2)^2.
    const std::vector<Vec2> loop = starLoop(Vec2(1e15, 1e15), 1.0);
    EXPECT_LE(latticeInside(loop, 0.01).size(), 202u * 202u);
}

TEST(PatchLattice, AnEdgeLengthGivingTooManyPointsIsAnError) {
    EXPECT_THROW(latticeInside(starLoop(Vec2(0, 0), 1.0), 1e-6), Error);
}

}  // namespace
}  // namespace rigmesh
