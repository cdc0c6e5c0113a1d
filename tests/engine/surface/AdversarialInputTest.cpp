// Hard but valid-looking outlines: each either inflates into a closed,
// manifold surface or is rejected with a rigmesh::Error.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <random>
#include <vector>

#include "SurfaceTestSupport.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

using surfacetest::expectSurfaceOrError;

constexpr double kHugeOffset = 1e8;
constexpr int kHugePointCount = 50000;
constexpr int kJitteryPointCount = 10000;
constexpr double kFineJitter = 0.001;   // radius noise below the outline spacing
constexpr double kCoarseJitter = 0.01;  // radius noise of a shaky hand
constexpr double kMinSpacingRatio = 0.5;

TEST(AdversarialInput, ThreePointTriangle) {
    expectSurfaceOrError({{0, 0}, {1, 0}, {0.3, 0.8}});
}

TEST(AdversarialInput, ThinSliverRectangle) {
    expectSurfaceOrError({{0, 0}, {1000, 0}, {1000, 1}, {0, 1}});
}

TEST(AdversarialInput, DenselySampledThinSliverRectangle) {
    std::vector<Vec2> sliver;
    testsupport::appendSegment(sliver, {0, 0}, {1000, 0}, 1.0);
    testsupport::appendSegment(sliver, {1000, 0}, {1000, 1}, 0.5);
    testsupport::appendSegment(sliver, {1000, 1}, {0, 1}, 1.0);
    testsupport::appendSegment(sliver, {0, 1}, {0, 0}, 0.5);
    expectSurfaceOrError(sliver);
}

// The paper notes the chordal axis of a circle is unstable: tiny noise
// decides where the junctions fall.
TEST(AdversarialInput, NearCircles) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-1e-4, 1e-4);
    for (int c = 0; c < 5; ++c) {
        SCOPED_TRACE("near circle " + std::to_string(c));
        expectSurfaceOrError(
            testsupport::polarOutline(100 + 50 * c, [&](double) { return 1.0 + jitter(random); }));
    }
}

// A band wound twice around the origin: long, curled and close to itself.
TEST(AdversarialInput, Spiral) {
    const double turns = 2.0, width = 0.25, pitch = 0.5;
    const int samples = 800;
    std::vector<Vec2> outer, inner;
    for (int i = 0; i <= samples; ++i) {
        const double theta = 2.0 * std::numbers::pi * turns * i / samples;
        const double r = 0.5 + pitch * theta / (2.0 * std::numbers::pi);
        const Vec2 direction(std::cos(theta), std::sin(theta));
        outer.push_back((r + width / 2) * direction);
        inner.push_back((r - width / 2) * direction);
    }
    std::vector<Vec2> spiral(outer.begin(), outer.end());
    spiral.insert(spiral.end(), inner.rbegin(), inner.rend());
    expectSurfaceOrError(spiral);
}

TEST(AdversarialInput, FiftyThousandPoints) {
    std::mt19937 random(50000);
    expectSurfaceOrError(
        testsupport::randomStarPolygon(random, kHugePointCount, kFineJitter, false));
}

// The cleaner's spacing is documented as a fraction of the bounding-box
// diagonal. Strict on purpose. Known defect: jitter in a dense stroke shrinks
// it (this 10k-point stroke with 1% radius jitter: 0.021 instead of about
// 0.059; 50k points: about 15 times too small), and the surface's target
// edge length with it.
TEST(AdversarialInput, JitteryDenseStrokeKeepsTheOutlineSpacing) {
    std::mt19937 random(10000);
    const auto stroke =
        testsupport::randomStarPolygon(random, kJitteryPointCount, kCoarseJitter, false);
    const CleanPolygon clean = cleanStroke(stroke);
    Eigen::AlignedBox2d box;
    for (const Vec2& p : clean.points)
        box.extend(p);
    const double expected = StrokeCleanOptions{}.relativeSpacing * box.diagonal().norm();
    EXPECT_GE(clean.spacing, kMinSpacingRatio * expected)
        << clean.points.size() << " outline points";
}

// A jittery 50k-point stroke once made the pipeline take over a minute (the
// outline spacing shrank with the jitter); the stroke's low-pass fixed it.
TEST(AdversarialInput, JitteryFiftyThousandPointStroke) {
    std::mt19937 random(50000);
    const auto stroke =
        testsupport::randomStarPolygon(random, kHugePointCount, kCoarseJitter, false);
    expectSurfaceOrError(stroke);
}

TEST(AdversarialInput, CoordinatesOffsetByHundredMillion) {
    std::vector<Vec2> tube = testsupport::sharedSketchPoints("tube");
    for (Vec2& p : tube)
        p += Vec2(kHugeOffset, -kHugeOffset);
    expectSurfaceOrError(tube);
}

TEST(AdversarialInput, StarOffsetByHundredMillion) {
    std::vector<Vec2> star = testsupport::sharedSketchPoints("star");
    for (Vec2& p : star)
        p += Vec2(kHugeOffset, kHugeOffset);
    expectSurfaceOrError(star);
}

}  // namespace
}  // namespace rigmesh
