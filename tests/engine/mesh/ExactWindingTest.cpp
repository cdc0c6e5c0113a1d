// The exact winding number (a ray's signed crossings) against the sum of
// solid angles it replaces where it can decide: the same integer on closed
// surfaces, nested and inside out; no answer on the surface; surfaces whose
// directed edges do not cancel are told apart.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "TestShapes.h"
#include "autorig/JointsInside.h"
#include "mesh/ExactWinding.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

using testshapes::append;
using testshapes::torus;

// The winding number as it was counted before the rays were batched: one
// point, every face (its box test included), along z, else x, else y.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;

Point3 point3(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

// The winding number counted along the ray from `point` along axis `k`;
// empty when the ray meets an edge or a vertex or the point is on a face.
std::optional<int> windingAlongOnePoint(const TriMesh& mesh, const Vec3& point, int k) {
    // The projection along the ray onto the plane of the two other axes,
    // in cyclic order (i, j, k), so that a left turn there is a face normal
    // with a positive k component.
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const auto along = [&](const Vec3& v) { return Point2(v[i], v[j]); };
    const Point2 q = along(point);
    const Point3 p = point3(point);
    int winding = 0;
    for (const auto& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3& b = mesh.vertices[face[1]];
        const Vec3& c = mesh.vertices[face[2]];
        // The ray {point + t e_k, t > 0} cannot meet a face wholly behind
        // the point or beside the ray.
        if (std::max({a[k], b[k], c[k]}) < point[k] || std::max({a[i], b[i], c[i]}) < point[i] ||
            std::min({a[i], b[i], c[i]}) > point[i] || std::max({a[j], b[j], c[j]}) < point[j] ||
            std::min({a[j], b[j], c[j]}) > point[j])
            continue;
        // The ray's line meets the face's interior where the point's
        // projection lies strictly inside the face's projection; the three
        // orientations then agree with the sign of the normal's k component.
        const CGAL::Orientation ab = CGAL::orientation(along(a), along(b), q);
        const CGAL::Orientation bc = CGAL::orientation(along(b), along(c), q);
        const CGAL::Orientation ca = CGAL::orientation(along(c), along(a), q);
        const bool onBorder =
            ab == CGAL::COLLINEAR || bc == CGAL::COLLINEAR || ca == CGAL::COLLINEAR;
        if (!onBorder && (ab != bc || bc != ca))
            continue;  // outside the projection
        if (onBorder) {
            // Strictly outside if two corners' orientations disagree anyway;
            // else the line may graze an edge or a vertex.
            const bool positive =
                ab == CGAL::LEFT_TURN || bc == CGAL::LEFT_TURN || ca == CGAL::LEFT_TURN;
            const bool negative =
                ab == CGAL::RIGHT_TURN || bc == CGAL::RIGHT_TURN || ca == CGAL::RIGHT_TURN;
            if (positive && negative)
                continue;
            return std::nullopt;
        }
        // Inside the projection: the ray meets the face if the point lies
        // on the side of its plane the ray leaves from. CGAL's orientation
        // of (a, b, c, p) is the sign of ((b - a) x (c - a)) . (p - a): the
        // point lies behind a face whose normal runs with the ray (the
        // projection turns left) when it is negative.
        const CGAL::Orientation side = CGAL::orientation(point3(a), point3(b), point3(c), p);
        if (side == CGAL::COPLANAR)
            return std::nullopt;  // on the face
        const bool normalAlongRay = ab == CGAL::LEFT_TURN;
        if (normalAlongRay && side == CGAL::NEGATIVE)
            ++winding;  // leaves through the face, along its normal
        else if (!normalAlongRay && side == CGAL::POSITIVE)
            --winding;  // leaves through the face, against its normal
    }
    return winding;
}

std::optional<int> windingOnePointAtATime(const TriMesh& mesh, const Vec3& point) {
    for (int k : {2, 0, 1})
        if (const std::optional<int> winding = windingAlongOnePoint(mesh, point, k))
            return winding;
    return std::nullopt;
}

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
    // On the boxes' bounds: a vertex's coordinate across each ray, and the
    // torus's plane of symmetry z = 0.
    for (int w = 0; w < nested.vertexCount(); w += 37) {
        const Vec3& corner = nested.vertices[w];
        points.emplace_back(corner.x(), corner.y() + 0.013, corner.z() - 0.5);
        points.emplace_back(corner.x() + 0.011, corner.y(), 0.0);
        points.emplace_back(corner.x() - 0.7, corner.y() + 0.017, corner.z());
    }
    points.emplace_back(0.0, 0.0, 0.0);
    const std::vector<std::optional<int>> batch = exactWindingNumbers(nested, points);
    ASSERT_EQ(batch.size(), points.size());
    for (std::size_t p = 0; p < points.size(); ++p) {
        SCOPED_TRACE(points[p].transpose());
        EXPECT_EQ(batch[p], windingOnePointAtATime(nested, points[p]));
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
    EXPECT_GE(decided, 203);
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
