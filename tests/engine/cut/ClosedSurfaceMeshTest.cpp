// The direct build of a closed surface as CGAL's Surface_mesh
// (mesh/CgalClosedSurface.h, what the cut's split starts from) against
// CGAL::Euler::add_face face by face (mesh/CgalSurfaceMesh's toSurfaceMesh):
// every vertex, halfedge and face index and every link the same, on the
// shared sketches' parts and spheres, also with their faces shuffled and
// their corners rotated (so that faces meet a vertex's earlier faces from
// both sides of a gap); and no surface where add_face's result is not a
// closed manifold.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

#include "SharedSketchPart.h"
#include "TestShapes.h"
#include "mesh/CgalClosedSurface.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

using cgal::SurfaceMesh;

void expectSameSurface(const SurfaceMesh& direct, const SurfaceMesh& euler,
                       const std::string& what) {
    ASSERT_EQ(direct.number_of_vertices(), euler.number_of_vertices()) << what;
    ASSERT_EQ(direct.number_of_halfedges(), euler.number_of_halfedges()) << what;
    ASSERT_EQ(direct.number_of_faces(), euler.number_of_faces()) << what;
    int differences = 0;
    for (auto v : euler.vertices())
        differences +=
            direct.halfedge(v) != euler.halfedge(v) || !(direct.point(v) == euler.point(v));
    for (auto h : euler.halfedges())
        differences += direct.target(h) != euler.target(h) || direct.next(h) != euler.next(h) ||
                       direct.prev(h) != euler.prev(h) || direct.face(h) != euler.face(h);
    for (auto f : euler.faces())
        differences += direct.halfedge(f) != euler.halfedge(f);
    EXPECT_EQ(differences, 0) << what;
}

void expectSameAsEuler(const TriMesh& mesh, const std::string& what) {
    const std::optional<SurfaceMesh> direct = cgal::closedSurfaceMesh(mesh);
    ASSERT_TRUE(direct.has_value()) << what;
    const SurfaceMesh euler =
        cgal::toSurfaceMesh(mesh, MessageId::PartSurfaceNotManifold, MessageId::PartSurfaceHasHole);
    expectSameSurface(*direct, euler, what);
}

TriMesh shuffled(TriMesh mesh, unsigned seed) {
    std::mt19937 random(seed);
    std::shuffle(mesh.faces.begin(), mesh.faces.end(), random);
    for (auto& face : mesh.faces)
        std::rotate(face.begin(), face.begin() + random() % 3, face.end());
    return mesh;
}

TEST(ClosedSurfaceMesh, GivesEulerAddFacesIndicesAndLinksOnSharedSketchParts) {
    int parts = 0;
    for (const std::string& sketch : testsupport::sharedSketchNames(false)) {
        const TriMesh& mesh = testsupport::sharedSketchPart(sketch).mesh;
        expectSameAsEuler(mesh, sketch);
        expectSameAsEuler(shuffled(mesh, 7), sketch + " shuffled");
        ++parts;
    }
    EXPECT_GT(parts, 10);
}

TEST(ClosedSurfaceMesh, GivesEulerAddFacesIndicesAndLinksOnShuffledSpheres) {
    for (int subdivisions = 0; subdivisions <= 3; ++subdivisions)
        for (unsigned seed = 1; seed <= 20; ++seed)
            expectSameAsEuler(
                shuffled(makeIcosphere(subdivisions, 1.0), seed),
                "icosphere " + std::to_string(subdivisions) + " seed " + std::to_string(seed));
}

// Apexes of 40 faces: more corners than CgalClosedSurface.h scans, sorted
// and searched instead.
TEST(ClosedSurfaceMesh, GivesEulerAddFacesIndicesAndLinksAroundVerticesOfManyFaces) {
    const TriMesh cone = testshapes::doubleCone(40);
    expectSameAsEuler(cone, "double cone");
    expectSameAsEuler(shuffled(cone, 7), "shuffled double cone");
    TriMesh flipped = cone;
    std::swap(flipped.faces[10][0], flipped.faces[10][1]);
    EXPECT_FALSE(cgal::closedSurfaceMesh(flipped));
    TriMesh doubled = cone;
    doubled.faces.push_back(doubled.faces[4]);
    EXPECT_FALSE(cgal::closedSurfaceMesh(doubled));
}

TEST(ClosedSurfaceMesh, LeavesSurfacesThatAreNotClosedManifoldsToEuler) {
    const TriMesh sphere = makeIcosphere(1, 1.0);
    TriMesh holed = sphere;
    holed.faces.pop_back();
    EXPECT_FALSE(cgal::closedSurfaceMesh(holed));

    TriMesh flipped = sphere;
    std::swap(flipped.faces[3][0], flipped.faces[3][1]);
    EXPECT_FALSE(cgal::closedSurfaceMesh(flipped));

    TriMesh degenerate = sphere;
    degenerate.faces[0][1] = degenerate.faces[0][0];
    EXPECT_FALSE(cgal::closedSurfaceMesh(degenerate));

    TriMesh isolated = sphere;
    isolated.vertices.push_back(Vec3(5.0, 0.0, 0.0));
    EXPECT_FALSE(cgal::closedSurfaceMesh(isolated));

    // Two spheres sharing one vertex (the second's leftmost is the first's
    // rightmost): closed and manifold at every edge, not at that vertex.
    int leftmost = 0, rightmost = 0;
    for (int v = 0; v < sphere.vertexCount(); ++v) {
        if (sphere.vertices[v].x() < sphere.vertices[leftmost].x())
            leftmost = v;
        if (sphere.vertices[v].x() > sphere.vertices[rightmost].x())
            rightmost = v;
    }
    TriMesh pinched = sphere;
    std::vector<int> index(sphere.vertexCount());
    for (int v = 0; v < sphere.vertexCount(); ++v) {
        if (v == leftmost) {
            index[v] = rightmost;
            continue;
        }
        index[v] = pinched.vertexCount();
        pinched.vertices.push_back(sphere.vertices[v] + Vec3(2.0, 0.0, 0.0));
    }
    for (auto face : sphere.faces) {
        for (int& v : face)
            v = index[v];
        pinched.faces.push_back(face);
    }
    EXPECT_FALSE(cgal::closedSurfaceMesh(pinched));
}

}  // namespace
}  // namespace rigmesh
