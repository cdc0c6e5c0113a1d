// Caps built as patches (surface/CapPatches.h): a cap that took in a big
// round lobe whole, whose slices would stand as a wall beside the concave
// corner at its base, is a connecting region with one port on the surface
// (stubs 22 and 35 of the creature family: walls of 2.2 and 2.5 spacings
// with the cap sliced), while the rig keeps the cap; no shared sketch has
// such a cap.
#include <gtest/gtest.h>

#include <algorithm>

#include "CreatureOutlines.h"
#include "SurfaceTestSupport.h"
#include "SurfaceWall.h"
#include "surface/SectionGaps.h"

namespace rigmesh {
namespace {

int capPatches(const Decomposition& regions) {
    return static_cast<int>(
        std::count_if(regions.connecting.begin(), regions.connecting.end(),
                      [](const ConnectingRegion& r) { return r.junctions.empty(); }));
}

int caps(const Decomposition& regions) {
    int count = 0;
    for (const CylinderRegion& c : regions.cylinders)
        count += (c.startCap.empty() ? 0 : 1) + (c.endCap.empty() ? 0 : 1);
    return count;
}

class CapPatch : public testing::TestWithParam<int> {};

TEST_P(CapPatch, IsAOnePortPatchOnTheSurfaceACapInTheRigAndStandsNoWall) {
    const auto outline =
        testsupport::creatureOutline(testsupport::CreatureClass::Stubs, GetParam());
    const SketchToSurfaceResult result = sketchToSurface(outline.stroke);
    ASSERT_TRUE(result.surfaceRegions.has_value());
    const Decomposition& surface = *result.surfaceRegions;
    ASSERT_EQ(capPatches(surface), 1);
    for (const ConnectingRegion& r : surface.connecting) {
        if (r.junctions.empty()) {
            EXPECT_EQ(r.ports.size(), 1u);
        }
    }
    // The rig has the cap the surface gave up.
    EXPECT_EQ(caps(result.decomposition), caps(surface) + 1);
    EXPECT_EQ(capPatches(result.decomposition), 0);
    for (const CylinderSections& c : result.surfaceCylinders)
        EXPECT_TRUE(sectionGaps(c, result.targetEdgeLength).empty());
    const double wall = surfacetest::deepestWall(result.surface.mesh, result.polygon.points).depth /
                        result.polygon.spacing;
    EXPECT_LT(wall, 2.0);  // SurfaceWall.h's limit
    // Every vertex is told in the rig's regions.
    for (const VertexOrigin& o : result.surface.origins)
        EXPECT_GE(o.region, 0);
}

INSTANTIATE_TEST_SUITE_P(StubsSeeds, CapPatch, testing::Values(22, 35));

class SharedSketchCaps : public testing::TestWithParam<std::string> {};

TEST_P(SharedSketchCaps, AreNeverBuiltAsPatches) {
    const SketchToSurfaceResult& result = surfacetest::sharedResult(GetParam());
    if (result.surfaceRegions) {
        EXPECT_EQ(capPatches(*result.surfaceRegions), 0);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SharedSketchCaps,
                         testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
