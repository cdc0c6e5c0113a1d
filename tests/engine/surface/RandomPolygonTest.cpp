// Random star-shaped outlines, some with narrow necks: each one either
// inflates into a closed, manifold surface or is rejected with a
// rigmesh::Error, never a crash or another exception.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

constexpr int kRandomCases = 200;
constexpr int kMinPoints = 20, kMaxPoints = 400;
constexpr double kMaxRadiusNoise = 0.1;
// Twice the default outline spacing: the surfaces have a quarter of the
// vertices, which keeps 200 cases within the suite's time budget, and thin
// necks are then narrower relative to the spacing, the harder case.
constexpr double kRelativeSpacing = 1.0 / 30.0;

TEST(RandomPolygons, GiveClosedManifoldSurfaceOrError) {
    std::mt19937 random(2012);
    std::uniform_int_distribution<int> pointCount(kMinPoints, kMaxPoints);
    std::uniform_real_distribution<double> noise(0.0, kMaxRadiusNoise);
    SketchToSurfaceOptions options;
    options.stroke.relativeSpacing = kRelativeSpacing;
    int built = 0, rejected = 0;
    for (int c = 0; c < kRandomCases; ++c) {
        SCOPED_TRACE("random polygon " + std::to_string(c));
        const bool neck = c % 4 == 0;
        const int count = pointCount(random);
        const auto polygon = testsupport::randomStarPolygon(random, count, noise(random), neck);
        const auto result = surfacetest::runPipeline(polygon, options);
        EXPECT_TRUE(result.outcome == surfacetest::Outcome::ClosedManifold ||
                    result.outcome == surfacetest::Outcome::Rejected)
            << result.detail;
        if (result.outcome == surfacetest::Outcome::Rejected) {
            EXPECT_FALSE(result.detail.empty());
        }
        built += result.outcome == surfacetest::Outcome::ClosedManifold ? 1 : 0;
        rejected += result.outcome == surfacetest::Outcome::Rejected ? 1 : 0;
    }
    RecordProperty("built", built);
    RecordProperty("rejected", rejected);
    // Smooth star-shaped outlines are the easy case: most must build.
    EXPECT_GT(built, kRandomCases / 2) << rejected << " rejected";
}

}  // namespace
}  // namespace rigmesh
