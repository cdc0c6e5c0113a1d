// Resolution follows thickness: the local edge length is
// at most CrossSectionOptions::radiusFraction of the local radius, so a thin
// part is round (at least 12 vertices around every body cross section), while
// a part wide enough keeps the document's edge length.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

// A stadium (rectangle with round ends) of the given length and radius, CCW,
// with points about `step` apart.
std::vector<Vec2> rod(double length, double radius, double step = 0.05) {
    std::vector<Vec2> points;
    const int end = std::max(8, static_cast<int>(std::ceil(std::numbers::pi * radius / step)));
    const int side = std::max(1, static_cast<int>(std::ceil(length / step)));
    for (int i = 0; i < end; ++i) {
        const double a = -std::numbers::pi / 2 + std::numbers::pi * i / end;
        points.emplace_back(length / 2 + radius * std::cos(a), radius * std::sin(a));
    }
    for (int i = 0; i < side; ++i)
        points.emplace_back(length / 2 - length * i / side, radius);
    for (int i = 0; i < end; ++i) {
        const double a = std::numbers::pi / 2 + std::numbers::pi * i / end;
        points.emplace_back(-length / 2 + radius * std::cos(a), radius * std::sin(a));
    }
    for (int i = 0; i < side; ++i)
        points.emplace_back(-length / 2 + length * i / side, -radius);
    return points;
}

TEST(ThicknessResolution, ALongThinRodIsRoundNotADiamond) {
    // 10 long, 0.25 thick, at an edge length of four times its radius: one
    // edge across each half ring (a diamond) if the edge length ruled alone.
    SketchToSurfaceOptions options;
    options.surface.targetEdgeLength = 1.0;
    const SketchToSurfaceResult result = sketchToSurface(rod(10.0, 0.25), options);
    const std::vector<int> sizes = surfacetest::ringSizes(result);
    ASSERT_FALSE(sizes.empty());
    EXPECT_GE(*std::min_element(sizes.begin(), sizes.end()), 12);
    const MeshReport report = analyseMesh(result.surface.mesh, false);
    EXPECT_TRUE(report.isClosed());
    EXPECT_TRUE(report.isManifold());
}

TEST(ThicknessResolution, EveryBodySectionOfTheSharedSketchesHasTwelveVerticesAround) {
    for (const std::string& name : testsupport::sharedSketchNames(false)) {
        const std::vector<int> sizes = surfacetest::ringSizes(surfacetest::sharedResult(name));
        if (!sizes.empty()) {
            EXPECT_GE(*std::min_element(sizes.begin(), sizes.end()), 12) << name;
        }
    }
}

TEST(ThicknessResolution, AWidePartKeepsTheTargetEdgeLength) {
    // A rod as wide as it can be for this edge length: its rings follow the
    // edge length, not the radius fraction.
    SketchToSurfaceOptions options;
    options.surface.targetEdgeLength = 0.1;
    const SketchToSurfaceResult result = sketchToSurface(rod(8.0, 2.0, 0.1), options);
    for (const auto& cylinder : result.cylinders)
        for (const CrossSection& s : cylinder.sections)
            if (!s.inCap && s.radius() * options.sections.radiusFraction > 0.1) {
                EXPECT_NEAR(s.spacing, 0.1, 1e-9);
            }
}

}  // namespace
}  // namespace rigmesh
