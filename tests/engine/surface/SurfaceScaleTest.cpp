// Scale invariance: every stage works relative to the stroke's size, so a
// scaled stroke gives the same mesh, scaled.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>
#include <vector>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

constexpr double kScaleTolerance = 1e-6;  // relative to the bounding-box diagonal

struct ScaleCase {
    std::string sketch;
    double scale;
};

// Faces as a set, each rotated to start at its smallest index.
std::set<std::array<int, 3>> faceSet(const TriMesh& mesh) {
    std::set<std::array<int, 3>> faces;
    for (std::array<int, 3> f : mesh.faces) {
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
        faces.insert(f);
    }
    return faces;
}

class SketchSurfaceScale : public ::testing::TestWithParam<ScaleCase> {};

TEST_P(SketchSurfaceScale, ScaledStrokeGivesScaledMesh) {
    const auto& [sketch, scale] = GetParam();
    const TriMesh& reference = surfacetest::sharedResult(sketch).surface.mesh;
    std::vector<Vec2> stroke = testsupport::sharedSketchPoints(sketch);
    for (Vec2& p : stroke)
        p *= scale;
    const TriMesh scaled = sketchToSurface(stroke).surface.mesh;

    ASSERT_EQ(scaled.vertexCount(), reference.vertexCount());
    ASSERT_EQ(scaled.faceCount(), reference.faceCount());
    // Same triangles; the order may differ (CGAL's face iteration order).
    EXPECT_EQ(faceSet(scaled), faceSet(reference));
    const double tolerance =
        kScaleTolerance * surfacetest::boundingBox(reference).diagonal().norm();
    double worst = 0.0;
    for (int v = 0; v < reference.vertexCount(); ++v)
        worst = std::max(worst, (scaled.vertices[v] / scale - reference.vertices[v]).norm());
    EXPECT_LE(worst, tolerance);
}

std::vector<ScaleCase> scaleCases() {
    std::vector<ScaleCase> cases;
    for (const std::string& sketch : testsupport::sharedSketchNames(false))
        for (double scale : {1e-3, 1e3})
            cases.push_back({sketch, scale});
    return cases;
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SketchSurfaceScale, ::testing::ValuesIn(scaleCases()),
                         [](const ::testing::TestParamInfo<ScaleCase>& param) {
                             return param.param.sketch +
                                    (param.param.scale < 1 ? "_times_1em3" : "_times_1e3");
                         });

}  // namespace
}  // namespace rigmesh
