// Every good shared sketch inflates into a clean, closed, genus-0 surface:
// topology, orientation, self-intersections and triangle quality.
#include <gtest/gtest.h>

#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

constexpr double kMinAngleDegrees = 5.0;

class SketchSurfaceTopology : public ::testing::TestWithParam<std::string> {
  protected:
    const MeshReport& report() const { return surfacetest::sharedReport(GetParam()); }
};

TEST_P(SketchSurfaceTopology, IsClosed) {
    EXPECT_TRUE(report().isClosed()) << report().boundaryEdges << " boundary edges";
}

TEST_P(SketchSurfaceTopology, IsManifold) {
    EXPECT_EQ(report().nonManifoldEdges, 0);
    EXPECT_EQ(report().nonManifoldVertices, 0);
}

TEST_P(SketchSurfaceTopology, IsConsistentlyOutwardOriented) {
    EXPECT_EQ(report().inconsistentlyOrientedEdges, 0);
    EXPECT_GT(report().volume, 0.0);
}

TEST_P(SketchSurfaceTopology, IsOneComponent) {
    EXPECT_EQ(report().components, 1);
}

TEST_P(SketchSurfaceTopology, HasGenusZero) {
    EXPECT_EQ(report().genus, 0) << "Euler characteristic " << report().eulerCharacteristic;
}

TEST_P(SketchSurfaceTopology, HasNoSelfIntersectingFaces) {
    EXPECT_EQ(report().selfIntersectingFacePairs, 0);
}

TEST_P(SketchSurfaceTopology, HasNoDegenerateFace) {
    EXPECT_EQ(report().degenerateFaces, 0);
}

// Strict on purpose. Known defect: camel_head's surface has a 4.45 degree
// angle (as of this writing); the test stays red until the engine is fixed.
TEST_P(SketchSurfaceTopology, HasNoSliverTriangle) {
    EXPECT_GE(report().minAngleDegrees, kMinAngleDegrees);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SketchSurfaceTopology,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
