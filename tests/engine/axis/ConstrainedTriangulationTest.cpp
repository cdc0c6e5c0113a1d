// The constrained Delaunay triangulation of simple polygons (paper 2.1):
// coverage, orientation, neighbour symmetry and rejection of crossings.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "SketchToSurfaceTestSupport.h"
#include "base/Error.h"
#include "geometry/ConstrainedTriangulation.h"

namespace rigmesh {
namespace {

using testsupport::cross2;
using testsupport::signedArea;

constexpr double kAreaRelativeTolerance = 1e-9;

double triangleArea(const PolygonTriangulation& cdt, const std::array<int, 3>& t) {
    return 0.5 * cross2(cdt.points[t[1]] - cdt.points[t[0]], cdt.points[t[2]] - cdt.points[t[0]]);
}

// Every invariant of the header, checked independently of the engine.
void expectValidTriangulation(const std::vector<Vec2>& polygon) {
    const PolygonTriangulation cdt = triangulatePolygon(polygon);
    const int n = static_cast<int>(polygon.size());
    ASSERT_EQ(cdt.points.size(), polygon.size());
    ASSERT_EQ(cdt.neighbors.size(), cdt.triangles.size());
    // A polygon triangulation without Steiner points has n - 2 triangles.
    EXPECT_EQ(static_cast<int>(cdt.triangles.size()), n - 2);

    double total = 0.0;
    for (std::size_t t = 0; t < cdt.triangles.size(); ++t) {
        const auto& tri = cdt.triangles[t];
        for (int v : tri) {
            ASSERT_GE(v, 0);
            ASSERT_LT(v, n);
        }
        const double area = triangleArea(cdt, tri);
        EXPECT_GT(area, 0.0) << "triangle " << t << " is not counter-clockwise";
        total += area;
        for (int k = 0; k < 3; ++k) {
            const int a = tri[(k + 1) % 3];
            const int b = tri[(k + 2) % 3];
            const int across = cdt.neighbors[t][k];
            if ((a + 1) % n == b || (b + 1) % n == a) {
                EXPECT_EQ(across, -1) << "polygon edge " << a << "-" << b << " has a neighbour";
                continue;
            }
            ASSERT_GE(across, 0) << "chord " << a << "-" << b << " has no neighbour";
            ASSERT_LT(across, static_cast<int>(cdt.triangles.size()));
            // Symmetry: the neighbour sees this triangle across the same edge, reversed.
            int back = -1;
            for (int j = 0; j < 3; ++j)
                if (cdt.neighbors[across][j] == static_cast<int>(t))
                    back = j;
            ASSERT_GE(back, 0) << "neighbours of " << t << " and " << across << " disagree";
            const auto& other = cdt.triangles[across];
            EXPECT_EQ(other[(back + 1) % 3], b);
            EXPECT_EQ(other[(back + 2) % 3], a);
        }
    }
    const double polygonArea = signedArea(polygon);
    EXPECT_NEAR(total, polygonArea, kAreaRelativeTolerance * polygonArea);
}

TEST(ConstrainedTriangulation, SquareIsCoveredByTwoTriangles) {
    expectValidTriangulation({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
}

TEST(ConstrainedTriangulation, LShapeIsCoveredExactly) {
    expectValidTriangulation({{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 3}, {0, 3}});
}

TEST(ConstrainedTriangulation, DenselySampledStadiumIsCoveredExactly) {
    expectValidTriangulation(testsupport::stadium(10.0, 0.5, 0.1));
}

TEST(ConstrainedTriangulation, RandomStarPolygonsAreCoveredExactly) {
    std::mt19937 random(20120601);
    std::uniform_int_distribution<int> count(5, 300);
    for (int c = 0; c < 40; ++c) {
        SCOPED_TRACE("star polygon " + std::to_string(c));
        expectValidTriangulation(
            testsupport::randomStarPolygon(random, count(random), 0.3, c % 3 == 0));
    }
}

TEST(ConstrainedTriangulation, SelfCrossingPolygonThrows) {
    const std::vector<Vec2> bowtie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
    EXPECT_THROW(triangulatePolygon(bowtie), Error);
}

TEST(ConstrainedTriangulation, SelfCrossingDenseLoopThrows) {
    // A figure eight sampled so that the crossing is far from any vertex.
    std::vector<Vec2> figure;
    for (int i = 0; i < 201; ++i) {
        const double theta = 2.0 * std::numbers::pi * i / 201;
        figure.emplace_back(std::cos(theta), 0.5 * std::sin(2.0 * theta));
    }
    EXPECT_THROW(triangulatePolygon(figure), Error);
}

TEST(ConstrainedTriangulation, FewerThanThreePointsThrow) {
    EXPECT_THROW(triangulatePolygon({{0, 0}, {1, 0}}), Error);
}

TEST(ConstrainedTriangulation, RepeatedPointThrows) {
    EXPECT_THROW(triangulatePolygon({{0, 0}, {1, 0}, {1, 1}, {1, 0}, {0, 1}}), Error);
}

}  // namespace
}  // namespace rigmesh
