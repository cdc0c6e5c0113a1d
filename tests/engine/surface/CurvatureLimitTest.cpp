// A cap's outline path keeps no corner sharper than a given radius
// (geometry/CurvatureLimit.h), and leaves rounder parts alone.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "geometry/CurvatureLimit.h"

namespace rigmesh {
namespace {

double largestCurvature(const std::vector<Vec2>& points) {
    double most = 0.0;
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        const Vec2 a = points[i] - points[i - 1], b = points[i + 1] - points[i];
        const double turn = std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
        most = std::max(most, turn / (0.5 * (a.norm() + b.norm())));
    }
    return most;
}

// Two legs of length 1 meeting at a right angle, sampled every 0.02.
std::vector<Vec2> rightAngle() {
    std::vector<Vec2> points;
    for (int i = 0; i <= 50; ++i)
        points.push_back(Vec2(-1.0 + 0.02 * i, 0.0));
    for (int i = 1; i <= 50; ++i)
        points.push_back(Vec2(0.0, 0.02 * i));
    return points;
}

TEST(CurvatureLimit, ARightAngleIsRoundedToTheRadiusAndItsEndsStay) {
    std::vector<Vec2> points = rightAngle();
    const std::vector<Vec2> before = points;
    constexpr double kRadius = 0.1;
    CurvatureFlow capPath;  // as a cap's outline path is rounded
    capPath.neighbourhood = 2;
    limitCurvature(points, kRadius, capPath);
    EXPECT_LE(largestCurvature(points), 1.0 / kRadius + 1e-9);
    EXPECT_EQ(points.front(), before.front());
    EXPECT_EQ(points.back(), before.back());
    // The corner is cut towards the inside of the turn (x < 0 < y) by about
    // the radius: a circle of radius r through both legs leaves the corner
    // r (sqrt 2 - 1) away.
    const Vec2 corner = points[50];
    EXPECT_LT(corner.x(), 1e-12);
    EXPECT_GT(corner.y(), -1e-12);
    EXPECT_GT((corner - before[50]).norm(), 0.2 * kRadius * (std::sqrt(2.0) - 1.0));
    EXPECT_LT((corner - before[50]).norm(), 2.0 * kRadius);
    // Far from the corner the legs are where they were.
    for (int i : {0, 5, 20, 80, 95, 100})
        EXPECT_LT((points[i] - before[i]).norm(), 1e-9) << i;
}

TEST(CurvatureLimit, AnArcRounderThanTheRadiusIsLeftExactly) {
    std::vector<Vec2> points;
    for (int i = 0; i <= 60; ++i) {
        const double t = std::numbers::pi * i / 60;
        points.push_back(Vec2(std::cos(t), std::sin(t)));  // radius 1
    }
    const std::vector<Vec2> before = points;
    CurvatureFlow capPath;
    capPath.neighbourhood = 2;
    limitCurvature(points, 0.5, capPath);
    EXPECT_EQ(points, before);
}

}  // namespace
}  // namespace rigmesh
