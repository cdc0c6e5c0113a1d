// isClosedOrientedManifold (mesh/MeshTopologyCheck.h): the fast verdict
// that a part's surface is a closed, manifold, consistently oriented one,
// and its agreement with analyseMeshTopology.
#include <gtest/gtest.h>

#include "TestShapes.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/MeshTopologyCheck.h"

namespace rigmesh {
namespace {

TEST(ClosedOrientedManifold, OnlyClosedOrientedManifoldsAreTakenForSurfaces) {
    const TriMesh ring = testshapes::torus(12, 8, 1.0, 0.3);
    EXPECT_TRUE(isClosedOrientedManifold(ring));
    EXPECT_TRUE(isClosedOrientedManifold(testshapes::box(Vec3::Zero(), Vec3::Ones())));
    TriMesh open = ring;
    open.faces.pop_back();
    EXPECT_FALSE(isClosedOrientedManifold(open));
    TriMesh flipped = ring;
    std::swap(flipped.faces[3][0], flipped.faces[3][1]);
    EXPECT_FALSE(isClosedOrientedManifold(flipped));
    TriMesh repeated = ring;
    repeated.faces[5][1] = repeated.faces[5][0];
    EXPECT_FALSE(isClosedOrientedManifold(repeated));
    // Two boxes sharing one corner: two fans around it.
    TriMesh pinched = testshapes::box(Vec3::Zero(), Vec3::Ones());
    testshapes::append(pinched, testshapes::box(Vec3::Ones(), Vec3::Constant(2.0)));
    for (auto& face : pinched.faces)
        for (int& v : face)
            if (v == 8)
                v = 7;
    EXPECT_FALSE(isClosedOrientedManifold(pinched));
    TriMesh outOfRange = ring;
    outOfRange.faces[0][2] = ring.vertexCount();
    EXPECT_FALSE(isClosedOrientedManifold(outOfRange));
    EXPECT_FALSE(isClosedOrientedManifold(TriMesh{}));
}

// A double cone's apexes have more faces than a vertex's corners are
// scanned for (MeshTopologyCheck.cpp sorts them).
TEST(ClosedOrientedManifold, JudgesVerticesWithManyFacesAsFew) {
    const TriMesh cone = testshapes::doubleCone(40);
    EXPECT_TRUE(isClosedOrientedManifold(cone));
    TriMesh flipped = cone;
    std::swap(flipped.faces[10][0], flipped.faces[10][1]);
    EXPECT_FALSE(isClosedOrientedManifold(flipped));
    TriMesh open = cone;
    open.faces.erase(open.faces.begin() + 6);
    EXPECT_FALSE(isClosedOrientedManifold(open));
    TriMesh doubled = cone;
    doubled.faces.push_back(doubled.faces[4]);
    EXPECT_FALSE(isClosedOrientedManifold(doubled));
    // Two cones whose top apexes are one vertex: two fans of 40 faces there.
    TriMesh pinched = cone;
    TriMesh other = cone;
    for (Vec3& p : other.vertices)
        p.z() = 2.0 - p.z();
    for (auto& face : other.faces)
        std::swap(face[0], face[1]);
    testshapes::append(pinched, other);
    const int otherTop = cone.vertexCount() + 40;
    for (auto& face : pinched.faces)
        for (int& v : face)
            if (v == otherTop)
                v = 40;
    EXPECT_FALSE(isClosedOrientedManifold(pinched));
    EXPECT_EQ(analyseMeshTopology(pinched).isManifold(), false);
}

// Wherever the fast check says yes, the full analysis finds nothing to
// refuse; wherever the analysis finds something, the fast check says no.
TEST(ClosedOrientedManifold, AgreesWithTheTopologyAnalysis) {
    std::vector<TriMesh> meshes{testshapes::torus(12, 8, 1.0, 0.3), testshapes::tetrahedron(),
                                testshapes::box(Vec3::Zero(), Vec3::Ones()), makeIcosphere(3, 1.0),
                                testshapes::doubleCone(40)};
    const std::size_t closed = meshes.size();
    for (std::size_t m = 0; m < closed; ++m) {
        TriMesh open = meshes[m];
        open.faces.erase(open.faces.begin());
        meshes.push_back(open);
        TriMesh flipped = meshes[m];
        std::swap(flipped.faces.back()[1], flipped.faces.back()[2]);
        meshes.push_back(flipped);
        TriMesh doubled = meshes[m];
        doubled.faces.push_back(doubled.faces.front());
        meshes.push_back(doubled);
    }
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const MeshReport report = analyseMeshTopology(meshes[m]);
        const bool solid =
            report.isClosed() && report.isManifold() && report.inconsistentlyOrientedEdges == 0;
        EXPECT_EQ(isClosedOrientedManifold(meshes[m]), solid) << "mesh " << m;
        EXPECT_EQ(solid, m < closed) << "mesh " << m;
    }
}

}  // namespace
}  // namespace rigmesh
