// Randomized strokes: star-shaped outlines always clean, self-crossing ones
// are always rejected, whatever their size, position, rotation or start.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "SketchTestShapes.h"
#include "SketchTestSupport.h"
#include "base/Error.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

constexpr double kPi = std::numbers::pi;

// Random size, position, rotation, direction and starting point.
std::vector<Vec2> randomlyPlaced(std::vector<Vec2> points, std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    if (unit(random) < 0.5) {
        std::reverse(points.begin(), points.end());
    }
    std::rotate(
        points.begin(),
        points.begin() + static_cast<long>(unit(random) * static_cast<double>(points.size())),
        points.end());
    const double scale = std::pow(10.0, -6.0 + 12.0 * unit(random));
    const Vec2 offset = scale * 10.0 * Vec2(unit(random) - 0.5, unit(random) - 0.5);
    return transformed(points, scale, 2.0 * kPi * unit(random), offset);
}

// A polygon whose vertices go once around the origin at increasing angles
// (with some spread) and random radii, densely sampled along its edges.
std::vector<Vec2> randomStarShape(std::mt19937& random) {
    std::uniform_int_distribution<int> vertexCount(3, 40);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int count = vertexCount(random);
    std::vector<Vec2> vertices;
    for (int i = 0; i < count; ++i) {
        const double angle = 2.0 * kPi * (i + 0.6 * (unit(random) - 0.5)) / count;
        const double radius = 0.35 + 0.65 * unit(random);
        vertices.push_back(radius * Vec2(std::cos(angle), std::sin(angle)));
    }
    std::vector<Vec2> stroke;
    const int perEdge = 1 + static_cast<int>(unit(random) * 8.0);
    for (int i = 0; i < count; ++i) {
        for (int k = 0; k < perEdge; ++k) {
            const double t = static_cast<double>(k) / perEdge;
            stroke.push_back((1.0 - t) * vertices[i] + t * vertices[(i + 1) % count]);
        }
    }
    return stroke;
}

// A figure eight (two equal lobes crossing at the origin) with jitter.
std::vector<Vec2> randomFigureEight(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double width = 1.0 + 2.0 * unit(random);
    const double height = 0.5 + 1.5 * unit(random);
    const int count = 50 + static_cast<int>(unit(random) * 350.0);
    std::vector<Vec2> stroke;
    for (int i = 0; i < count; ++i) {
        const double t = 2.0 * kPi * i / count;
        const Vec2 jitter = 0.005 * width * Vec2(unit(random) - 0.5, unit(random) - 0.5);
        stroke.push_back(Vec2(width * std::sin(t), height * std::sin(t) * std::cos(t)) + jitter);
    }
    return stroke;
}

// A bow tie: two triangles touching at the crossing of their long edges.
std::vector<Vec2> randomBowTie(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(-0.15, 0.15);
    const std::vector<Vec2> corners{{0.0 + unit(random), 0.0 + unit(random)},
                                    {1.0 + unit(random), 1.0 + unit(random)},
                                    {1.0 + unit(random), 0.0 + unit(random)},
                                    {0.0 + unit(random), 1.0 + unit(random)}};
    std::vector<Vec2> stroke;
    for (std::size_t i = 0; i < corners.size(); ++i) {
        for (int k = 0; k < 20; ++k) {
            stroke.push_back(corners[i] + (corners[(i + 1) % 4] - corners[i]) * (k / 20.0));
        }
    }
    return stroke;
}

TEST(RandomStrokes, StarShapedOutlinesAlwaysCleanIntoSimplePolygons) {
    std::mt19937 random(2012);
    for (int trial = 0; trial < 300; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const auto stroke = randomlyPlaced(randomStarShape(random), random);
        CleanPolygon clean;
        ASSERT_NO_THROW(clean = cleanStroke(stroke));
        expectSimpleCounterClockwise(clean.points);
        EXPECT_GE(clean.points.size(), 60u);
        EXPECT_LE(clean.points.size(), 400u);
    }
}

TEST(RandomStrokes, FigureEightsAreAlwaysRejectedAsSelfCrossing) {
    std::mt19937 random(1989);
    for (int trial = 0; trial < 200; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const auto stroke = randomlyPlaced(randomFigureEight(random), random);
        try {
            cleanStroke(stroke);
            FAIL() << "a self-crossing stroke was accepted";
        } catch (const Error& error) {
            EXPECT_NE(std::string(error.what()).find("crosses itself"), std::string::npos)
                << error.what();
        }
    }
}

TEST(RandomStrokes, BowTiesAreAlwaysRejectedAsSelfCrossing) {
    std::mt19937 random(42);
    for (int trial = 0; trial < 200; ++trial) {
        SCOPED_TRACE("trial " + std::to_string(trial));
        const auto stroke = randomlyPlaced(randomBowTie(random), random);
        try {
            cleanStroke(stroke);
            FAIL() << "a self-crossing stroke was accepted";
        } catch (const Error& error) {
            EXPECT_NE(std::string(error.what()).find("crosses itself"), std::string::npos)
                << error.what();
        }
    }
}

}  // namespace
}  // namespace rigmesh
