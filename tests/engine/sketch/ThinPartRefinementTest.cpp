// Outline resolution follows thickness: thin stretches of the
// cleaned outline get points along a smooth spline, wide ones keep theirs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "SketchToSurfaceTestSupport.h"
#include "sketch/ThinPartRefinement.h"

namespace rigmesh {
namespace {

// Distance from p to the closed polygon's nearest edge.
double distanceToPolygon(const std::vector<Vec2>& polygon, const Vec2& p) {
    double best = INFINITY;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
        best = std::min(best, (a + t * (b - a) - p).norm());
    }
    return best;
}

TEST(OutlineWidths, AStadiumIsItsDiameterAcrossAlongItsSides) {
    const double radius = 0.3, step = 0.05;
    const auto stadium = testsupport::stadium(4.0, radius, step);
    const std::vector<double> width = outlineWidths(stadium, 10.0);
    for (std::size_t i = 0; i < stadium.size(); ++i) {
        if (stadium[i].x() > 0.5 && stadium[i].x() < 3.5) {
            EXPECT_NEAR(width[i], 2 * radius, step) << i;
        }
    }
}

TEST(ThinPartRefinement, AWideOutlineKeepsItsPoints) {
    const auto circle = testsupport::polarOutline(120, [](double) { return 1.0; });
    const double spacing = 2 * std::numbers::pi / 120;
    EXPECT_EQ(refineThinParts(circle, spacing), circle);
}

TEST(ThinPartRefinement, AThinLimbGetsPointsAtAThirdOfItsWidthOnASmoothCurve) {
    // A limb 0.1 across sampled every 0.1: its round end has three points.
    const double radius = 0.05, spacing = 0.1;
    const auto limb = testsupport::stadium(3.0, radius, spacing);
    const auto refined = refineThinParts(limb, spacing);
    ASSERT_GT(refined.size(), 2 * limb.size());
    // Every original point is kept, in order.
    std::size_t next = 0;
    for (const Vec2& p : refined)
        if (next < limb.size() && p == limb[next])
            ++next;
    EXPECT_EQ(next, limb.size());
    // Pieces are at most about a third of the width (0.1 / 3), and the new
    // points stay close to the outline drawn.
    for (std::size_t i = 0; i < refined.size(); ++i) {
        EXPECT_LT((refined[(i + 1) % refined.size()] - refined[i]).norm(), 0.045) << i;
        EXPECT_LT(distanceToPolygon(limb, refined[i]), 0.02) << i;
    }
    EXPECT_GT(testsupport::signedArea(refined), 0.0);
}

}  // namespace
}  // namespace rigmesh
