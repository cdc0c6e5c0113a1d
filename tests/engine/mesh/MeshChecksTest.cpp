#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "TestShapes.h"
#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/MeshSelfIntersections.h"

namespace rigmesh {
namespace {

using testshapes::append;
using testshapes::tetrahedron;
using testshapes::torus;

// An icosphere with 4 subdivisions is inscribed in the sphere and loses a
// little volume to its flat faces.
constexpr double kIcosphereVolumeRelativeTolerance = 0.01;
constexpr double kFloatTolerance = 1e-12;  // relative, for sums of a few thousand terms

TEST(MeshChecks, IcosphereIsWatertightGenus0AndOutward) {
    const double radius = 2.0;
    const MeshReport report = analyseMesh(makeIcosphere(4, radius));
    EXPECT_EQ(report.vertices, 2562);
    EXPECT_EQ(report.faces, 5120);
    EXPECT_TRUE(report.isClosed());
    EXPECT_TRUE(report.isManifold());
    EXPECT_TRUE(report.isOutwardOriented());
    EXPECT_TRUE(report.isWatertightGenus0());
    EXPECT_EQ(report.components, 1);
    EXPECT_EQ(report.eulerCharacteristic, 2);
    EXPECT_EQ(report.genus, 0);
    EXPECT_EQ(report.degenerateFaces, 0);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);

    const double sphereVolume = 4.0 / 3.0 * std::numbers::pi * std::pow(radius, 3);
    EXPECT_LT(report.volume, sphereVolume);
    EXPECT_NEAR(report.volume, sphereVolume, kIcosphereVolumeRelativeTolerance * sphereVolume);
    const double sphereArea = 4 * std::numbers::pi * radius * radius;
    EXPECT_NEAR(report.area, sphereArea, kIcosphereVolumeRelativeTolerance * sphereArea);
    // Subdivided icosahedron triangles stay close to equilateral.
    EXPECT_GT(report.minAngleDegrees, 45.0);
    EXPECT_LT(report.maxAngleDegrees, 80.0);
}

TEST(MeshChecks, TorusHasGenusOne) {
    const MeshReport report = analyseMesh(torus(24, 12, 3.0, 1.0));
    EXPECT_TRUE(report.isClosed());
    EXPECT_TRUE(report.isManifold());
    EXPECT_TRUE(report.isOutwardOriented());
    EXPECT_EQ(report.eulerCharacteristic, 0);
    EXPECT_EQ(report.genus, 1);
    EXPECT_FALSE(report.isWatertightGenus0());
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
}

TEST(MeshChecks, CylinderTubeIsClosedWithTheExactPrismVolume) {
    const int segments = 32;
    const double radius = 0.5, length = 3.0;
    const MeshReport report = analyseMesh(makeCylinderTube(5, segments, radius, length));
    EXPECT_EQ(report.faces, 2 * segments * 5);
    EXPECT_TRUE(report.isWatertightGenus0());
    EXPECT_TRUE(report.isOutwardOriented());
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
    // The cross-section is a regular polygon inscribed in the circle.
    const double polygonArea =
        segments / 2.0 * radius * radius * std::sin(2 * std::numbers::pi / segments);
    EXPECT_NEAR(report.volume, polygonArea * length, kFloatTolerance * polygonArea * length);
}

TEST(MeshChecks, RemovingAFaceLeavesThreeBoundaryEdges) {
    TriMesh mesh = makeIcosphere(2, 1.0);
    const std::array<int, 3> removed = mesh.faces.back();
    mesh.faces.pop_back();
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.boundaryEdges, 3);
    EXPECT_FALSE(report.isClosed());
    EXPECT_EQ(report.genus, -1);
    EXPECT_FALSE(report.isWatertightGenus0());
    EXPECT_TRUE(report.isManifold());

    // The hole's edges run opposite to the removed face.
    auto edges = boundaryEdgeList(mesh);
    std::sort(edges.begin(), edges.end());
    std::vector<std::array<int, 2>> expected = {
        {removed[1], removed[0]}, {removed[2], removed[1]}, {removed[0], removed[2]}};
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(edges, expected);
}

TEST(MeshChecks, FlippedFaceMakesItsThreeEdgesInconsistent) {
    TriMesh mesh = makeIcosphere(2, 1.0);
    std::swap(mesh.faces[7][1], mesh.faces[7][2]);
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.inconsistentlyOrientedEdges, 3);
    EXPECT_FALSE(report.isOutwardOriented());
    EXPECT_FALSE(report.isWatertightGenus0());
    // The surface itself is still a closed sphere without intersections.
    EXPECT_TRUE(report.isClosed());
    EXPECT_TRUE(report.isManifold());
    EXPECT_EQ(report.genus, 0);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
}

TEST(MeshChecks, InsideOutMeshHasNegativeVolume) {
    TriMesh mesh = makeIcosphere(1, 1.0);
    for (auto& face : mesh.faces)
        std::swap(face[1], face[2]);
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.inconsistentlyOrientedEdges, 0);
    EXPECT_LT(report.volume, 0);
    EXPECT_FALSE(report.isOutwardOriented());
}

TEST(MeshChecks, OverlappingSpheresInOneSoupSelfIntersect) {
    TriMesh mesh = makeIcosphere(2, 1.0);
    TriMesh shifted = makeIcosphere(2, 1.0);
    for (Vec3& v : shifted.vertices)
        v.x() += 0.5;
    append(mesh, shifted);
    const MeshReport report = analyseMesh(mesh);
    EXPECT_GT(report.selfIntersectingFacePairs, 0);
    EXPECT_EQ(report.components, 2);
    EXPECT_EQ(report.genus, -1);  // two components
    EXPECT_TRUE(report.isManifold());
}

TriMesh overlappingSpheres(double offset) {
    TriMesh mesh = makeIcosphere(2, 1.0);
    TriMesh shifted = makeIcosphere(2, 1.0);
    for (Vec3& v : shifted.vertices)
        v += Vec3(offset, 0.3 * offset, 0.1);
    append(mesh, shifted);
    return mesh;
}

TEST(MeshChecks, SoupCountMatchesPmpOnASurfaceMesh) {
    TriMesh tubeThroughSphere = makeIcosphere(3, 1.0);
    append(tubeThroughSphere, makeCylinderTube(6, 24, 0.3, 3.0));
    for (const TriMesh& mesh : {overlappingSpheres(0.5), overlappingSpheres(1.2),
                                overlappingSpheres(2.5), tubeThroughSphere}) {
        const int reference = countSelfIntersectingFacePairsWithSurfaceMesh(mesh);
        ASSERT_GE(reference, 0);
        EXPECT_EQ(countSelfIntersectingFacePairs(mesh), reference);
    }
    EXPECT_EQ(countSelfIntersectingFacePairsWithSurfaceMesh(overlappingSpheres(2.5)), 0);
}

TEST(MeshChecks, NonManifoldSoupStillCountsItsIntersections) {
    const TriMesh spheres = overlappingSpheres(0.5);
    const int reference = countSelfIntersectingFacePairsWithSurfaceMesh(spheres);

    // A far-away fin makes the soup non-manifold; PMP cannot take it any more.
    TriMesh withFin = spheres;
    const int base = withFin.vertexCount();
    for (const Vec3& v :
         {Vec3(10, 0, 0), Vec3(11, 0, 0), Vec3(10, 1, 0), Vec3(10, -1, 0), Vec3(10, 0, 1)})
        withFin.vertices.push_back(v);
    withFin.faces.push_back({base, base + 1, base + 2});
    withFin.faces.push_back({base + 1, base, base + 3});
    withFin.faces.push_back({base, base + 1, base + 4});
    EXPECT_EQ(countSelfIntersectingFacePairsWithSurfaceMesh(withFin), -1);
    const MeshReport report = analyseMesh(withFin);
    EXPECT_EQ(report.nonManifoldEdges, 1);
    EXPECT_EQ(report.selfIntersectingFacePairs, reference);
}

TEST(MeshChecks, FinOfThreeFacesOnOneEdgeIsNonManifold) {
    TriMesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    mesh.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.nonManifoldEdges, 1);
    EXPECT_FALSE(report.isManifold());
    EXPECT_EQ(report.boundaryEdges, 6);
    EXPECT_EQ(report.genus, -1);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);  // the fins only share their edge
}

TEST(MeshChecks, CoplanarFacesFoldedOntoASharedEdgeIntersect) {
    TriMesh mesh;
    mesh.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.5, 0.5, 0}};
    mesh.faces = {{0, 1, 2}, {1, 0, 3}};
    EXPECT_EQ(analyseMesh(mesh).selfIntersectingFacePairs, 1);
}

TEST(MeshChecks, TetrahedraTouchingAtOneVertexMakeItNonManifold) {
    TriMesh mesh = tetrahedron();
    TriMesh other = tetrahedron();
    // Mirror the second through the origin so the two touch only at vertex 0.
    for (Vec3& v : other.vertices)
        v = -v;
    for (auto& face : other.faces)
        std::swap(face[1], face[2]);
    const int base = mesh.vertexCount();
    append(mesh, other);
    for (auto& face : mesh.faces)
        for (int& index : face)
            if (index == base)
                index = 0;  // weld the shared corner
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.nonManifoldVertices, 1);
    EXPECT_EQ(report.nonManifoldEdges, 0);
    EXPECT_EQ(report.boundaryEdges, 0);
    EXPECT_EQ(report.components, 1);
    EXPECT_FALSE(report.isManifold());
    EXPECT_EQ(report.genus, -1);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
    EXPECT_GT(report.volume, 0);
}

TEST(MeshChecks, RepeatedVertexIndexFaceIsDegenerate) {
    TriMesh mesh = tetrahedron();
    mesh.faces.push_back({0, 0, 1});
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.degenerateFaces, 1);
    // The degenerate face stays out of the topology.
    EXPECT_TRUE(report.isWatertightGenus0());
}

TEST(MeshChecks, DegenerateFaceFailsTheChecks) {
    TriMesh mesh = tetrahedron();
    EXPECT_TRUE(analyseMesh(mesh).passesChecks());
    mesh.faces.push_back({0, 0, 1});
    EXPECT_FALSE(analyseMesh(mesh).passesChecks());
}

TEST(MeshChecks, CountDegenerateFacesAgreesWithTheFullReport) {
    TriMesh mesh = tetrahedron();
    EXPECT_EQ(countDegenerateFaces(mesh), 0);
    mesh.faces.push_back({0, 0, 1});        // repeated index
    mesh.vertices.emplace_back(0.5, 0, 0);  // on the edge 0-1
    mesh.faces.push_back({0, 1, 4});        // zero area
    EXPECT_EQ(countDegenerateFaces(mesh), 2);
    EXPECT_EQ(countDegenerateFaces(mesh), analyseMesh(mesh).degenerateFaces);
}

TEST(MeshChecks, VolumeFarFromTheOriginIsExactAsAtTheOrigin) {
    const double radius = 2.0;
    const TriMesh atOrigin = makeIcosphere(4, radius);
    const double reference = analyseMesh(atOrigin, false).volume;
    TriMesh moved = atOrigin;
    for (Vec3& v : moved.vertices)
        v += Vec3(3e8, -3e8, 3e8);
    const MeshReport report = analyseMesh(moved, false);
    // Cones to the world origin lost the volume to cancellation at 3e8.
    EXPECT_NEAR(report.volume, reference, 1e-6 * reference);
    EXPECT_TRUE(report.isOutwardOriented());
}

TEST(MeshChecks, CollinearFaceIsDegenerate) {
    TriMesh mesh = tetrahedron();
    mesh.vertices.emplace_back(0.5, 0, 0);
    mesh.faces.push_back({0, 1, 4});
    const MeshReport report = analyseMesh(mesh);
    EXPECT_EQ(report.degenerateFaces, 1);
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);  // degenerate faces are counted separately
}

TEST(MeshChecks, EmptyMeshReportsNothingAndIsNotClosed) {
    const MeshReport report = analyseMesh(TriMesh{});
    EXPECT_EQ(report.faces, 0);
    EXPECT_EQ(report.components, 0);
    EXPECT_EQ(report.genus, -1);
    EXPECT_FALSE(report.isClosed());
    EXPECT_EQ(report.selfIntersectingFacePairs, 0);
}

TEST(MeshChecks, SkippingSelfIntersectionsReportsMinusOne) {
    EXPECT_EQ(analyseMesh(tetrahedron(), false).selfIntersectingFacePairs, -1);
}

TEST(MeshChecks, OutOfRangeIndexThrowsInsteadOfCrashing) {
    TriMesh mesh = tetrahedron();
    mesh.faces.push_back({0, 1, 9});
    EXPECT_THROW(analyseMesh(mesh), Error);
}

TEST(MeshChecks, TenThousandFaceTubeIsWatertightGenus0) {
    // 2 * 100 * 50 = 10000 faces; its speed is measured by bench_sketch_to_surface, not here.
    const TriMesh mesh = makeCylinderTube(50, 100, 1.0, 4.0);
    ASSERT_EQ(mesh.faceCount(), 10000);
    EXPECT_TRUE(analyseMesh(mesh).isWatertightGenus0());
}

}  // namespace
}  // namespace rigmesh
