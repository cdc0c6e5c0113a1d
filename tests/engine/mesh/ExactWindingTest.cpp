// The exact winding number (a ray's signed crossings) against the sum of
// solid angles it replaces where it can decide: the same integer on closed
// surfaces, nested and inside out; no answer on the surface; surfaces whose
// directed edges do not cancel are told apart.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "TestShapes.h"
#include "autorig/JointsInside.h"
#include "mesh/ExactWinding.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

using testshapes::append;
using testshapes::torus;

void expectSameAsSolidAngles(const TriMesh& mesh, double extent, int points) {
    ASSERT_TRUE(directedEdgesCancel(mesh));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-extent, extent);
    int decided = 0;
    for (int i = 0; i < points; ++i) {
        const Vec3 p(unit(random), unit(random), unit(random));
        const std::optional<int> exact = exactWindingNumber(mesh, p);
        if (!exact)
            continue;
        ++decided;
        EXPECT_EQ(*exact, std::lround(windingNumber(mesh, p))) << p.transpose();
    }
    EXPECT_EQ(decided, points);  // random points are in general position
}

TEST(ExactWinding, MatchesTheSolidAnglesAroundASphere) {
    expectSameAsSolidAngles(makeIcosphere(3, 1.0), 1.5, 400);
}

TEST(ExactWinding, MatchesTheSolidAnglesAroundATorusAndNestedSpheres) {
    expectSameAsSolidAngles(torus(24, 12, 1.0, 0.4), 1.6, 400);
    TriMesh nested = makeIcosphere(2, 1.0);
    append(nested, makeIcosphere(2, 0.5));
    expectSameAsSolidAngles(nested, 1.2, 400);
    EXPECT_EQ(exactWindingNumber(nested, Vec3(0.01, 0.02, 0.03)), 2);
}

TEST(ExactWinding, CountsAnInsideOutSurfaceNegatively) {
    TriMesh flipped = makeIcosphere(2, 1.0);
    for (auto& face : flipped.faces)
        std::swap(face[1], face[2]);
    EXPECT_EQ(exactWindingNumber(flipped, Vec3(0.1, 0.05, -0.02)), -1);
    EXPECT_EQ(exactWindingNumber(flipped, Vec3(1.1, 0.05, -0.02)), 0);
}

TEST(ExactWinding, GivesNoAnswerOnTheSurfaceAndTriesAnotherAxisAlongAVertex) {
    const TriMesh sphere = makeIcosphere(1, 1.0);
    EXPECT_FALSE(exactWindingNumber(sphere, sphere.vertices[0]).has_value());
    const Vec3 onFace = (sphere.vertices[sphere.faces[0][0]] + sphere.vertices[sphere.faces[0][1]] +
                         sphere.vertices[sphere.faces[0][2]]) /
                        3.0;
    // The centroid of a face, rounded: on it or a hair off it; either way
    // the count may not be wrong.
    const std::optional<int> there = exactWindingNumber(sphere, onFace);
    if (there) {
        EXPECT_TRUE(*there == 0 || *there == 1);
    }
    // The rays from a point straight below a vertex along z meet that
    // vertex: another axis decides.
    const Vec3& v = sphere.vertices[0];
    EXPECT_EQ(exactWindingNumber(sphere, Vec3(v.x(), v.y(), v.z() - 3.0)), 0);
}

TEST(ExactWinding, TellsSurfacesWhoseEdgesDoNotCancel) {
    TriMesh open = makeIcosphere(2, 1.0);
    open.faces.pop_back();
    EXPECT_FALSE(directedEdgesCancel(open));
    TriMesh inconsistent = makeIcosphere(2, 1.0);
    std::swap(inconsistent.faces[0][1], inconsistent.faces[0][2]);
    EXPECT_FALSE(directedEdgesCancel(inconsistent));
    EXPECT_TRUE(directedEdgesCancel(makeIcosphere(2, 1.0)));
}

}  // namespace
}  // namespace rigmesh
