// The surface covers a pruned bump off a body while the rig does not see it
// (pipeline/RigRegionOrigins.h): the rig's regions are the
// paper's, and every vertex origin names one of them.
#include <gtest/gtest.h>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

void expectOriginsInTheRigsRegions(const SketchToSurfaceResult& result) {
    const auto& d = result.decomposition;
    for (std::size_t v = 0; v < result.surface.origins.size(); ++v) {
        const VertexOrigin& o = result.surface.origins[v];
        if (o.kind == RegionKind::Cylindrical) {
            ASSERT_GE(o.region, 0) << v;
            ASSERT_LT(o.region, static_cast<int>(d.cylinders.size())) << v;
            EXPECT_LT(o.section, static_cast<int>(result.cylinders[o.region].sections.size())) << v;
        } else {
            EXPECT_LT(o.region, static_cast<int>(d.connecting.size())) << v;
        }
    }
}

TEST(RigRegionOrigins, ABodyBumpIsCoveredWhileTheRigKeepsOneCylinder) {
    const SketchToSurfaceResult result = sketchToSurface(testsupport::blobWithBump());
    // The rig: one cylinder with two caps, as without the bump patch.
    ASSERT_EQ(result.decomposition.cylinders.size(), 1u);
    EXPECT_TRUE(result.decomposition.connecting.empty());
    expectOriginsInTheRigsRegions(result);
    // The surface reaches the bump's top (y = 1.45).
    double top = -1;
    for (const Vec3& p : result.surface.mesh.vertices)
        top = std::max(top, p.y());
    EXPECT_GT(top, 1.4);
}

TEST(RigRegionOrigins, EveryOriginOfTheSharedSketchesNamesARigRegion) {
    for (const std::string& name : testsupport::sharedSketchNames(false)) {
        SCOPED_TRACE(name);
        expectOriginsInTheRigsRegions(surfacetest::sharedResult(name));
    }
}

}  // namespace
}  // namespace rigmesh
