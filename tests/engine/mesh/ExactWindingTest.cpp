// The exact winding number (a ray's signed crossings) against the sum of
// solid angles it replaces where it can decide: the same integer on closed
// surfaces, nested and inside out; no answer on the surface; surfaces whose
// directed edges do not cancel are told apart.
#include <gtest/gtest.h>

#include <algorithm>
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

TEST(ExactWinding, GivesEachPointOfABatchWhatItsSolidAnglesOrItsOwnRaysGive) {
    // Random points with points on a vertex, straight below one (their z ray
    // meets it), sharing a coordinate with others, and on the plane of many
    // edges: a point that cannot be decided must not spoil the others.
    TriMesh nested = torus(24, 12, 1.0, 0.4);
    append(nested, makeIcosphere(2, 0.3));
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.5, 1.5);
    std::vector<Vec3> points;
    for (int i = 0; i < 200; ++i)
        points.emplace_back(unit(random), unit(random), unit(random));
    const Vec3 v = nested.vertices[5];
    points.push_back(v);
    points.emplace_back(v.x(), v.y(), v.z() - 2.0);
    points.emplace_back(points[0].x(), points[1].y(), points[2].z());
    points.emplace_back(points[0].x(), points[0].y(), points[3].z());
    points.emplace_back(0.0, 0.0, 0.0);
    const std::vector<std::optional<int>> batch = exactWindingNumbers(nested, points);
    ASSERT_EQ(batch.size(), points.size());
    for (std::size_t p = 0; p < points.size(); ++p) {
        SCOPED_TRACE(points[p].transpose());
        EXPECT_EQ(batch[p], exactWindingNumber(nested, points[p]));
        if (batch[p]) {
            EXPECT_EQ(*batch[p], std::lround(windingNumber(nested, points[p])));
        }
    }
    // Undecided: the point on a vertex, and the centre, whose rays along
    // every axis meet the inner sphere's vertices on the axes.
    EXPECT_FALSE(batch[200].has_value());
    EXPECT_FALSE(batch.back().has_value());
    const auto decided = std::count_if(batch.begin(), batch.end(),
                                       [](const std::optional<int>& w) { return w.has_value(); });
    EXPECT_EQ(decided, static_cast<long>(points.size()) - 2);
    EXPECT_TRUE(exactWindingNumbers(nested, {}).empty());
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
