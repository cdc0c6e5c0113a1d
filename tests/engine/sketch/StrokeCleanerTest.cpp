// Cleaning strokes: invariances, closing, resampling, smoothing, orientation.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include "SketchTestShapes.h"
#include "SketchTestSupport.h"
#include "base/Error.h"
#include "sketch/Sketch.h"
#include "sketch/StrokeCleaner.h"
#include "sketch/StrokeClosing.h"

namespace rigmesh {
namespace {

const char* const kGoodSketches[] = {"banana",    "biped",      "camel_body", "camel_head",
                                     "camel_leg", "camel_neck", "kinked",     "open_gap",
                                     "star",      "tube",       "y_branch"};

std::vector<Vec2> sharedPoints(const std::string& name) {
    return readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json").points;
}

std::string cleaningError(const std::vector<Vec2>& points, const StrokeCleanOptions& options = {}) {
    try {
        cleanStroke(points, options);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST(StrokeCleaner, ScalingTheInputScalesTheResult) {
    for (const char* name : kGoodSketches) {
        SCOPED_TRACE(name);
        const auto points = sharedPoints(name);
        const CleanPolygon reference = cleanStroke(points);
        const double size = boundingBoxDiagonal(reference.points);
        for (const double factor : {1e-3, 1e3}) {
            const CleanPolygon scaled = cleanStroke(transformed(points, factor));
            ASSERT_EQ(scaled.points.size(), reference.points.size());
            EXPECT_NEAR(scaled.spacing / factor, reference.spacing, 1e-9 * reference.spacing);
            double worst = 0.0;
            for (std::size_t i = 0; i < scaled.points.size(); ++i) {
                worst = std::max(worst, (scaled.points[i] / factor - reference.points[i]).norm());
            }
            EXPECT_LE(worst, 1e-9 * size) << "scale " << factor;
        }
    }
}

TEST(StrokeCleaner, RotatingOrRestartingTheOutlineKeepsItsAreaWithinOnePercent) {
    for (const char* name : kGoodSketches) {
        SCOPED_TRACE(name);
        const CleanPolygon reference = cleanStroke(sharedPoints(name));
        const double area = signedArea(reference.points);
        std::vector<Vec2> restarted = reference.points;
        std::rotate(restarted.begin(), restarted.begin() + restarted.size() / 3, restarted.end());
        const CleanPolygon again = cleanStroke(transformed(restarted, 1.0, 0.7, Vec2(3.0, -2.0)));
        EXPECT_NEAR(signedArea(again.points), area, 0.01 * area);
        expectSimpleCounterClockwise(again.points);
    }
}

TEST(StrokeCleaner, ClockwiseInputComesOutCounterClockwise) {
    const CleanPolygon clean = cleanStroke(circleStroke(200, -1.0));
    expectSimpleCounterClockwise(clean.points);
}

TEST(StrokeCleaner, SmoothingDoesNotShrinkACircle) {
    const CleanPolygon clean = cleanStroke(circleStroke(300, 1.0, 2.0));
    EXPECT_NEAR(signedArea(clean.points), std::numbers::pi * 4.0, 0.01 * std::numbers::pi * 4.0);
    for (const Vec2& p : clean.points) {
        EXPECT_NEAR(p.norm(), 2.0, 0.01);
    }
}

TEST(StrokeCleaner, SmoothingRemovesMouseJitter) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    std::vector<Vec2> noisy = circleStroke(400, 1.0);
    for (Vec2& p : noisy) {
        p += Vec2(jitter(random), jitter(random));
    }
    const auto roughness = [](const std::vector<Vec2>& points) {
        double sum = 0.0;
        for (const Vec2& p : points) {
            sum += std::abs(p.norm() - 1.0);
        }
        return sum / static_cast<double>(points.size());
    };
    const CleanPolygon clean = cleanStroke(noisy);
    EXPECT_LT(roughness(clean.points), 0.6 * roughness(noisy));
}

TEST(StrokeCleaner, OvershootThatCrossesTheStartIsTrimmedAtTheCrossing) {
    // 1.15 turns whose radius shrinks from 1.04 to 0.96: the extra part
    // crosses the beginning of the stroke.
    const auto stroke = circleStroke(230, 1.15, 1.04, Vec2::Zero(), 0.0, -0.08 * 1.15);
    CleanPolygon clean;
    ASSERT_NO_THROW(clean = cleanStroke(stroke));
    expectSimpleCounterClockwise(clean.points);
    EXPECT_NEAR(signedArea(clean.points), std::numbers::pi, 0.05 * std::numbers::pi);
}

TEST(StrokeCleaner, OvershootThatSlidesPastTheStartIsTrimmed) {
    // The radius grows, so the extra part passes outside the beginning
    // without crossing it; closing it naively would cross the stroke.
    const auto stroke = circleStroke(230, 1.15, 1.0, Vec2::Zero(), 0.0, 0.06 * 1.15);
    CleanPolygon clean;
    ASSERT_NO_THROW(clean = cleanStroke(stroke));
    expectSimpleCounterClockwise(clean.points);
    EXPECT_NEAR(signedArea(clean.points), std::numbers::pi * 1.03 * 1.03, 0.05 * std::numbers::pi);
}

TEST(StrokeClosing, AStrokeReturnsToItsStartOnlyWhenItsEndsMeetWithinATenthOfItsSize) {
    // Of a unit circle (diagonal 2.83, so a tolerance of 0.28): half of it
    // (a gap of 2), 80% (a gap of 1.2) and 96.5% (a gap of 0.22).
    EXPECT_FALSE(returnsToStart(circleStroke(81, 0.5)));
    EXPECT_FALSE(returnsToStart(circleStroke(161, 0.8)));
    EXPECT_TRUE(returnsToStart(circleStroke(194, 0.97)));
    // Overshoots that cross or slide past the start are closed loops.
    EXPECT_TRUE(returnsToStart(circleStroke(230, 1.15, 1.04, Vec2::Zero(), 0.0, -0.08 * 1.15)));
    EXPECT_TRUE(returnsToStart(circleStroke(230, 1.15, 1.0, Vec2::Zero(), 0.0, 0.06 * 1.15)));
    // Repeated points neither help nor hurt; three distinct points are no loop.
    std::vector<Vec2> repeated;
    for (const Vec2& p : circleStroke(194, 0.97)) {
        repeated.push_back(p);
        repeated.push_back(p);
    }
    EXPECT_TRUE(returnsToStart(repeated));
    EXPECT_FALSE(returnsToStart({Vec2(0, 0), Vec2(1, 0), Vec2(1, 0), Vec2(0, 0.001)}));
}

TEST(StrokeCleaner, GapIsClosedWithAStraightSegment) {
    // 80% of a circle: the chord over the missing 72 degrees closes it.
    const auto stroke = circleStroke(161, 0.8 * 161.0 / 160.0);
    const CleanPolygon clean = cleanStroke(stroke);
    expectSimpleCounterClockwise(clean.points);
    const double gap = 2.0 * std::numbers::pi * 0.2;
    const double expected = std::numbers::pi - (gap - std::sin(gap)) / 2.0;
    EXPECT_NEAR(signedArea(clean.points), expected, 0.01 * expected);
    // Some points lie on the chord, well inside the circle.
    const Vec2 chordMiddle = Vec2(1.0 + std::cos(-gap), std::sin(-gap)) / 2.0;
    double closest = INFINITY;
    for (const Vec2& p : clean.points) {
        closest = std::min(closest, (p - chordMiddle).norm());
    }
    EXPECT_LT(closest, 1.5 * clean.spacing);
}

TEST(StrokeCleaner, ExplicitlyClosedStrokeKeepsItsShape) {
    const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    const CleanPolygon clean = cleanStroke(square);
    expectSimpleCounterClockwise(clean.points);
    EXPECT_NEAR(signedArea(clean.points), 1.0, 0.02);
    EXPECT_NE(clean.points.front(), clean.points.back());
}

TEST(StrokeCleaner, TriangleOfThreeDistinctPointsCleans) {
    const CleanPolygon clean = cleanStroke({{0, 0}, {1, 0}, {0, 1}});
    expectSimpleCounterClockwise(clean.points);
    EXPECT_NEAR(signedArea(clean.points), 0.5, 0.02);
}

TEST(StrokeCleaner, AbsoluteSpacingOverridesRelativeSpacing) {
    StrokeCleanOptions options;
    options.spacing = 0.1;
    const CleanPolygon clean = cleanStroke(circleStroke(300, 1.0), options);
    EXPECT_EQ(clean.points.size(), 63u);
    EXPECT_NEAR(clean.spacing, 0.1, 0.002);
    expectUniformSpacing(clean, 1.05);
}

TEST(StrokeCleaner, RelativeSpacingControlsThePointCount) {
    StrokeCleanOptions coarse;
    coarse.relativeSpacing = 1.0 / 30.0;
    const auto stroke = sharedPoints("tube");
    const std::size_t fine = cleanStroke(stroke).points.size();
    const std::size_t few = cleanStroke(stroke, coarse).points.size();
    EXPECT_NEAR(static_cast<double>(few), fine / 2.0, 3.0);
}

TEST(StrokeCleaner, WithoutSmoothingTheSamplesLieOnTheInput) {
    StrokeCleanOptions options;
    options.smoothingIterations = 0;
    const CleanPolygon clean = cleanStroke(circleStroke(500, 1.0), options);
    for (const Vec2& p : clean.points) {
        EXPECT_NEAR(p.norm(), 1.0, 1e-4);
    }
}

// Options come from code, never from a user: bad ones are programming errors
// (std::logic_error, docs/ARCHITECTURE.md's error rules), still named.
std::string optionsError(const std::vector<Vec2>& points, const StrokeCleanOptions& options) {
    try {
        cleanStroke(points, options);
    } catch (const std::logic_error& error) {
        return error.what();
    }
    return "";
}

TEST(StrokeCleaner, InvalidOptionsAreRejectedAsProgrammingErrors) {
    StrokeCleanOptions zero;
    zero.relativeSpacing = 0.0;
    EXPECT_NE(optionsError(circleStroke(50, 1.0), zero).find("spacing"), std::string::npos);
    StrokeCleanOptions negative;
    negative.smoothingIterations = -1;
    EXPECT_NE(optionsError(circleStroke(50, 1.0), negative).find("smoothing"), std::string::npos);
}

TEST(StrokeCleaner, NonFinitePointIsRejectedWithItsIndex) {
    auto stroke = circleStroke(50, 1.0);
    stroke[17].y() = INFINITY;
    const std::string message = cleaningError(stroke);
    EXPECT_NE(message.find("Point 17"), std::string::npos) << message;
}

TEST(StrokeCleaner, StrokeThatRunsBackAlongItselfIsRejected) {
    // Out along an L and back 1e-4 away: a wide hull but no area inside.
    std::vector<Vec2> stroke;
    for (int i = 0; i <= 50; ++i) {
        stroke.emplace_back(i * 0.2, 0.0);
    }
    for (int i = 1; i <= 50; ++i) {
        stroke.emplace_back(10.0, i * 0.2);
    }
    for (int i = 50; i >= 0; --i) {
        stroke.emplace_back(10.0 - 1e-4, i * 0.2);
    }
    for (int i = 50; i >= 1; --i) {
        stroke.emplace_back(i * 0.2, 1e-4);
    }
    const std::string message = cleaningError(stroke);
    EXPECT_TRUE(message.find("almost no area") != std::string::npos ||
                message.find("crosses itself") != std::string::npos)
        << message;
}

}  // namespace
}  // namespace rigmesh
