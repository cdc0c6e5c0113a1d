// Good outlines give no degenerate face: a cap tip that falls on an end point
// of the cap's last section (as on a circle) used to leave a collapsed strip
// triangle with a repeated vertex.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

std::vector<Vec2> circle(int points, double radius) {
    std::vector<Vec2> stroke;
    for (int i = 0; i < points; ++i) {
        const double angle = 2 * std::numbers::pi * i / points;
        stroke.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    return stroke;
}

TEST(DegenerateFaces, CircleGivesClosedSurfaceWithoutDegenerateFaces) {
    for (int points : {64, 200, 1000}) {
        const MeshReport report = analyseMesh(sketchToSurface(circle(points, 1.0)).surface.mesh);
        EXPECT_EQ(report.degenerateFaces, 0) << points << " points";
        EXPECT_TRUE(report.isWatertightGenus0()) << points << " points";
    }
}

TEST(DegenerateFaces, SharedSketchesGiveNoDegenerateFaces) {
    for (const std::string& sketch : testsupport::sharedSketchNames(false))
        EXPECT_EQ(surfacetest::sharedReport(sketch).degenerateFaces, 0) << sketch;
}

}  // namespace
}  // namespace rigmesh
