// A sketch whose surface would cross itself is refused with the reason and
// where (pipeline/SurfaceLimits: checkBuiltMesh): a 5-point needle built a
// surface with crossing face pairs, the CLI wrote it and exited 0, and merge,
// cut and `rigmesh rig` then refused the program's own output. That needle
// now builds without crossings (tests/data/sketches/README.md); a longer
// one still crosses itself at its far tip and is refused.
#include <gtest/gtest.h>

#include "SurfaceTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshSelfIntersections.h"
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

// The built surface is its own mirror image in the sketch plane, and its
// crossings are looked for on its upper half and the faces at the plane
// (mesh/MeshSelfIntersections.h). A crossing made by moving one vertex of
// each half straight through the surface, up and down, exactly mirrored, is
// found by that test as by the test of every face: the same pairs.
TEST(SelfIntersectingSurface, MirroredCrossingIsFoundOnTheUpperHalfAsOnTheWholeSurface) {
    const SketchToSurfaceResult result = sketchToSurface(testsupport::sharedSketchPoints("tube"));
    const TriMesh& mesh = result.surface.mesh;
    const std::vector<int>& mirror = result.surface.mirror;
    EXPECT_TRUE(selfIntersectingFacePairs(mesh).empty());
    EXPECT_TRUE(selfIntersectingFacePairs(mesh, mirror).empty());

    // The top vertex through the bottom, its image through the top.
    int top = 0;
    for (int v = 0; v < mesh.vertexCount(); ++v)
        if (mesh.vertices[v].z() > mesh.vertices[top].z())
            top = v;
    ASSERT_NE(mirror[top], top);
    TriMesh pierced = mesh;
    const double height = mesh.vertices[top].z();
    pierced.vertices[top].z() = -2.0 * height;
    pierced.vertices[mirror[top]].z() = 2.0 * height;
    const auto all = selfIntersectingFacePairs(pierced);
    EXPECT_FALSE(all.empty());
    EXPECT_EQ(selfIntersectingFacePairs(pierced, mirror), all);
    EXPECT_THROW(checkBuiltMesh(pierced, mirror), Error);

    // Moved through the sketch plane only, the vertex's faces cross their own
    // images (an upper face against a lower one).
    TriMesh dipped = mesh;
    dipped.vertices[top].z() = -0.5 * height;
    dipped.vertices[mirror[top]].z() = 0.5 * height;
    const auto across = selfIntersectingFacePairs(dipped);
    EXPECT_FALSE(across.empty());
    EXPECT_EQ(selfIntersectingFacePairs(dipped, mirror), across);

    // Not an exact mirror image (one image a little off): every face is
    // tested, still the same pairs.
    TriMesh uneven = pierced;
    uneven.vertices[mirror[top]].z() += 1e-9;
    EXPECT_EQ(selfIntersectingFacePairs(uneven, mirror), selfIntersectingFacePairs(uneven));
}

// Two triangles through each other high above the sketch plane, mirrored:
// a crossing within each half; and one triangle through the plane meeting its
// own image along the plane.
TEST(SelfIntersectingSurface, MirroredTrianglesCrossWithinAHalfAndAcrossThePlane) {
    const auto mirrored = [](const std::vector<Vec3>& upper,
                             const std::vector<std::array<int, 3>>& faces) {
        TriMesh mesh;
        mesh.vertices = upper;
        const int n = static_cast<int>(upper.size());
        for (const Vec3& p : upper)
            mesh.vertices.emplace_back(p.x(), p.y(), -p.z());
        mesh.faces = faces;
        for (const auto& [a, b, c] : faces)
            mesh.faces.push_back({a + n, c + n, b + n});
        std::vector<int> mirror(2 * n);
        for (int v = 0; v < n; ++v) {
            mirror[v] = v + n;
            mirror[v + n] = v;
        }
        return std::pair{mesh, mirror};
    };
    const auto [within, withinMirror] = mirrored({Vec3(0, 0, 5), Vec3(2, 0, 5), Vec3(1, 2, 5),
                                                  Vec3(1, 1, 4), Vec3(1, 1, 6), Vec3(1.5, -1, 5)},
                                                 {{0, 1, 2}, {3, 4, 5}});
    EXPECT_EQ(selfIntersectingFacePairs(within).size(), 2u);
    EXPECT_EQ(selfIntersectingFacePairs(within, withinMirror), selfIntersectingFacePairs(within));

    const auto [across, acrossMirror] = mirrored(
        {Vec3(0, 0, 1), Vec3(2, 0, 1), Vec3(1, 1, -1), Vec3(5, 0, 1), Vec3(7, 0, 1), Vec3(6, 1, 2)},
        {{0, 1, 2}, {3, 4, 5}});
    const auto pairs = selfIntersectingFacePairs(across);
    ASSERT_EQ(pairs.size(), 1u);
    EXPECT_EQ(pairs.front(), (std::array<int, 2>{0, 2}));
    EXPECT_EQ(selfIntersectingFacePairs(across, acrossMirror), pairs);
}

}  // namespace
}  // namespace rigmesh
