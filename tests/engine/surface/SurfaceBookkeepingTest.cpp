// Vertex bookkeeping for the rig and local updates: every vertex knows its
// region, and cylindrical vertices their cross section and axis position.
#include <gtest/gtest.h>

#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

class SketchSurfaceBookkeeping : public ::testing::TestWithParam<std::string> {
  protected:
    const SketchToSurfaceResult& result() const { return surfacetest::sharedResult(GetParam()); }
};

TEST_P(SketchSurfaceBookkeeping, EveryVertexHasAnOrigin) {
    EXPECT_EQ(result().surface.origins.size(), result().surface.mesh.vertices.size());
    EXPECT_EQ(result().cylinders.size(), result().decomposition.cylinders.size());
}

TEST_P(SketchSurfaceBookkeeping, CylinderAxisPositionsRiseFromZeroToTheEndTip) {
    for (std::size_t c = 0; c < result().cylinders.size(); ++c) {
        const CylinderSections& cylinder = result().cylinders[c];
        ASSERT_EQ(cylinder.axisPosition.size(), cylinder.sections.size()) << "cylinder " << c;
        double previous = 0.0;
        for (double position : cylinder.axisPosition) {
            EXPECT_GE(position, previous) << "cylinder " << c;
            previous = position;
        }
        EXPECT_GE(cylinder.endTipPosition, previous) << "cylinder " << c;
    }
}

TEST_P(SketchSurfaceBookkeeping, CylindricalVerticesKnowTheirSectionAndPosition) {
    const auto& origins = result().surface.origins;
    const int cylinders = static_cast<int>(result().cylinders.size());
    for (std::size_t v = 0; v < origins.size(); ++v) {
        const VertexOrigin& origin = origins[v];
        if (origin.kind != RegionKind::Cylindrical)
            continue;
        ASSERT_GE(origin.region, 0) << "vertex " << v;
        ASSERT_LT(origin.region, cylinders) << "vertex " << v;
        const CylinderSections& cylinder = result().cylinders[origin.region];
        const int sections = static_cast<int>(cylinder.sections.size());
        ASSERT_GE(origin.section, -1) << "vertex " << v;
        ASSERT_LT(origin.section, sections) << "vertex " << v;
        EXPECT_GE(origin.axisPosition, 0.0) << "vertex " << v;
        EXPECT_LE(origin.axisPosition, cylinder.endTipPosition) << "vertex " << v;
        if (origin.section >= 0) {
            EXPECT_EQ(origin.axisPosition, cylinder.axisPosition[origin.section]) << "vertex " << v;
        } else {
            // A tip: the start tip at 0, the end tip at endTipPosition.
            EXPECT_TRUE(origin.onOutline) << "tip vertex " << v;
            EXPECT_TRUE((origin.axisPosition == 0.0 && cylinder.startTip) ||
                        (origin.axisPosition == cylinder.endTipPosition && cylinder.endTip))
                << "tip vertex " << v << " at " << origin.axisPosition;
        }
    }
}

TEST_P(SketchSurfaceBookkeeping, ConnectingVerticesReferenceAConnectingRegion) {
    const auto& origins = result().surface.origins;
    const int regions = static_cast<int>(result().decomposition.connecting.size());
    int connecting = 0;
    for (std::size_t v = 0; v < origins.size(); ++v) {
        if (origins[v].kind != RegionKind::Connecting)
            continue;
        ++connecting;
        EXPECT_GE(origins[v].region, 0) << "vertex " << v;
        EXPECT_LT(origins[v].region, regions) << "vertex " << v;
        EXPECT_EQ(origins[v].section, -1) << "vertex " << v;
    }
    EXPECT_EQ(connecting > 0, regions > 0);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SketchSurfaceBookkeeping,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
