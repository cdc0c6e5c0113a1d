// A sketch whose surface would cross itself is refused with the reason and
// where (pipeline/SurfaceLimits: checkBuiltMesh): a 5-point needle built a
// surface with crossing face pairs, the CLI wrote it and exited 0, and merge,
// cut and `rigmesh rig` then refused the program's own output. That needle
// now builds without crossings (tests/data/sketches/README.md); a longer
// one still crosses itself at its far tip and is refused.
#include <gtest/gtest.h>

#include "SurfaceTestSupport.h"
#include "base/Error.h"
#include "mesh/SurfaceQuality.h"
#include "pipeline/SurfaceLimits.h"

namespace rigmesh {
namespace {

TEST(SelfIntersectingSurface, ANeedleWhoseSurfaceCrossesItselfIsRefusedSayingWhere) {
    const Sketch needle = readSketchFile(RIGMESH_TEST_DATA "/sketches/needle_crossing.json");
    try {
        sketchToSurface(needle.points);
        FAIL() << "the needle's crossing surface was accepted";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::SurfaceSelfIntersecting) << error.what();
        ASSERT_EQ(error.message().args.size(), 3u);
        EXPECT_GT(std::stoi(error.message().args[0]), 0);
        // Where: a point of the sketch's own box (0..11.6 by 0..0.061), in
        // its coordinates.
        const double x = std::stod(error.message().args[1]);
        const double y = std::stod(error.message().args[2]);
        EXPECT_GE(x, -0.5);
        EXPECT_LE(x, 12.1);
        EXPECT_GE(y, -0.5);
        EXPECT_LE(y, 0.6);
    }
}

// The first needle's surface crossed itself where its notch folded the
// outline; relaxing that fold at the outline (surface/FoldRelaxation)
// leaves it closed, without crossings and within the fold limit.
TEST(SelfIntersectingSurface, TheNotchedNeedleIsBuiltWithoutCrossings) {
    const Sketch needle = readSketchFile(RIGMESH_TEST_DATA "/sketches/needle.json");
    const SketchToSurfaceResult result = sketchToSurface(needle.points);
    const MeshReport report = analyseMesh(result.surface.mesh);
    EXPECT_TRUE(report.passesChecks());
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
    EXPECT_LE(normalAngles(result.surface.mesh).max, 35.0);
}

TEST(SelfIntersectingSurface, BuiltMeshCheckRefusesCrossingFacesOnly) {
    // Two triangles through each other, and the same two apart.
    TriMesh crossing;
    crossing.vertices = {Vec3(0, 0, 0),  Vec3(2, 0, 0), Vec3(1, 2, 0),
                         Vec3(1, 1, -1), Vec3(1, 1, 1), Vec3(1.5, -1, 0)};
    crossing.faces = {{0, 1, 2}, {3, 4, 5}};
    EXPECT_THROW(checkBuiltMesh(crossing), Error);
    TriMesh apart = crossing;
    for (int v = 3; v < 6; ++v)
        apart.vertices[v].x() += 10.0;
    EXPECT_NO_THROW(checkBuiltMesh(apart));
}

}  // namespace
}  // namespace rigmesh
