// Junction silhouettes do not shrink. The outline vertices
// of connecting regions are held by Least-Squares Meshes, so after smoothing
// they still lie on the cleaned outline, in the sketch plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

double distanceToPolygon(const std::vector<Vec2>& polygon, const Vec2& p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        const Vec2 ab = b - a;
        const double t =
            ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        best = std::min(best, (p - (a + t * ab)).norm());
    }
    return best;
}

class JunctionOutline : public testing::TestWithParam<std::string> {};

// A junction's silhouette never shrinks: its outline vertices lie on the
// sketch, or outside it where the surface's outline rounds a concave corner
// (sketch/ConcaveCorners.h: a crotch's apex is filled, never cut).
TEST_P(JunctionOutline, ConnectingOutlineVerticesStayOnTheSketchOrFillItsConcaveCorners) {
    const SketchToSurfaceResult& result = surfacetest::sharedResult(GetParam());
    const auto& outline = result.polygon.points;
    const double tolerance = 1e-9 * result.targetEdgeLength * 1e3;
    for (std::size_t v = 0; v < result.surface.origins.size(); ++v) {
        const VertexOrigin& o = result.surface.origins[v];
        if (o.kind != RegionKind::Connecting || !o.onOutline)
            continue;
        const Vec3& p = result.surface.mesh.vertices[v];
        EXPECT_EQ(p.z(), 0.0);
        const bool onSketch = distanceToPolygon(outline, p.head<2>()) <= tolerance;
        EXPECT_TRUE(onSketch || !testsupport::insidePolygon(outline, p.head<2>()))
            << "vertex " << v << " cuts into the sketch";
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, JunctionOutline,
                         testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
