// Hostile inputs: the cleaner either cleans them or throws rigmesh::Error;
// it never crashes, hangs or returns non-finite points.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

#include "SketchTestShapes.h"
#include "SketchTestSupport.h"
#include "base/Error.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

// Cleans `stroke`; a result must be a finite simple polygon. Returns the
// error message, or "" on success.
std::string cleanOrExplain(const std::vector<Vec2>& stroke) {
    try {
        const CleanPolygon clean = cleanStroke(stroke);
        for (const Vec2& p : clean.points) {
            EXPECT_TRUE(p.allFinite());
        }
        EXPECT_TRUE(std::isfinite(clean.spacing));
        return "";
    } catch (const Error& error) {
        EXPECT_GT(std::string(error.what()).size(), 20u);
        return error.what();
    }
}

TEST(AdversarialStrokes, EmptyStrokeIsRejected) {
    EXPECT_NE(cleanOrExplain({}).find("only 0 distinct points"), std::string::npos);
}

TEST(AdversarialStrokes, AllPointsEqualIsRejected) {
    const std::vector<Vec2> same(1000, Vec2(3.0, -4.0));
    EXPECT_NE(cleanOrExplain(same).find("only 1 distinct point"), std::string::npos);
}

TEST(AdversarialStrokes, ManyCopiesOfAFewPointsAreRejected) {
    std::vector<Vec2> stroke;
    for (const Vec2& p : {Vec2(0, 0), Vec2(1, 0), Vec2(0, 1), Vec2(1, 1)}) {
        stroke.insert(stroke.end(), 100000, p);
    }
    EXPECT_NE(cleanOrExplain(stroke).find("distinct positions"), std::string::npos);
}

// Its speed belongs to the benchmarks; here it must simply come out right.
TEST(AdversarialStrokes, MillionPointCircleCleansIntoTheCircle) {
    std::mt19937 random(1);
    std::uniform_real_distribution<double> jitter(-1e-3, 1e-3);
    auto stroke = circleStroke(1000000, 1.0);
    for (Vec2& p : stroke) {
        p += Vec2(jitter(random), jitter(random));
    }
    const CleanPolygon clean = cleanStroke(stroke);
    expectSimpleCounterClockwise(clean.points);
    EXPECT_NEAR(signedArea(clean.points), M_PI, 0.02 * M_PI);
}

TEST(AdversarialStrokes, MillionRandomPointsNeverCrash) {
    std::mt19937 random(2);
    std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
    std::vector<Vec2> stroke;
    for (int i = 0; i < 1000000; ++i) {
        stroke.emplace_back(coordinate(random), coordinate(random));
    }
    EXPECT_NE(cleanOrExplain(stroke), "");
}

TEST(AdversarialStrokes, HugeAndTinyCoordinatesCleanLikeUnitOnes) {
    const auto unit = circleStroke(200, 1.0);
    const CleanPolygon reference = cleanStroke(unit);
    for (const double scale : {1e12, 1e-12, 1e150, 1e-150}) {
        SCOPED_TRACE(scale);
        const CleanPolygon clean = cleanStroke(transformed(unit, scale, 0.0, Vec2(scale, -scale)));
        ASSERT_EQ(clean.points.size(), reference.points.size());
        for (std::size_t i = 0; i < clean.points.size(); ++i) {
            const Vec2 back = clean.points[i] / scale - Vec2(1.0, -1.0);
            EXPECT_NEAR((back - reference.points[i]).norm(), 0.0, 1e-9);
        }
    }
}

TEST(AdversarialStrokes, ExtremeMagnitudesNeverCrash) {
    const double big = std::numeric_limits<double>::max();
    const double small = std::numeric_limits<double>::denorm_min();
    cleanOrExplain({{-big, -big}, {big, -big}, {big, big}, {-big, big}});
    cleanOrExplain(transformed(circleStroke(100, 1.0), big / 4.0));
    cleanOrExplain(transformed(circleStroke(100, 1.0), small * 16.0));
    cleanOrExplain({{0, 0}, {small, 0}, {0, small}});
    cleanOrExplain({{0, 0}, {1e300, 0}, {0, 1e-300}, {-1e300, 1e300}});
    cleanOrExplain(transformed(circleStroke(100, 1.0), 1e-6, 0.0, Vec2(1e12, 1e12)));
}

TEST(AdversarialStrokes, SpikesAndZigZagsNeverCrash) {
    std::vector<Vec2> zigzag;
    for (int i = 0; i < 100000; ++i) {
        zigzag.emplace_back(i * 1e-5, (i % 2) * 1.0);
    }
    cleanOrExplain(zigzag);
    auto spiky = circleStroke(500, 1.0);
    spiky[250] *= 1e9;
    cleanOrExplain(spiky);
    cleanOrExplain(circleStroke(3000, 7.0));  // seven turns around
}

TEST(AdversarialStrokes, ExtremeOptionsNeverCrash) {
    StrokeCleanOptions tiny;
    tiny.spacing = 1e-12;
    EXPECT_NE(cleanOrExplain({{0, 0}, {1, 0}, {0, 1}}).size(), 1u);
    EXPECT_THROW(cleanStroke(circleStroke(100, 1.0), tiny), Error);
    StrokeCleanOptions huge;
    huge.relativeSpacing = 1e6;
    const CleanPolygon coarse = cleanStroke(circleStroke(100, 1.0), huge);
    EXPECT_GE(coarse.points.size(), 3u);
    StrokeCleanOptions nanSpacing;
    nanSpacing.relativeSpacing = std::nan("");
    EXPECT_THROW(cleanStroke(circleStroke(100, 1.0), nanSpacing), std::logic_error);
    StrokeCleanOptions manySmoothing;
    manySmoothing.smoothingIterations = 1000;
    cleanOrExplain(circleStroke(100, 1.0));
    EXPECT_NO_THROW(cleanStroke(circleStroke(100, 1.0), manySmoothing));
}

}  // namespace
}  // namespace rigmesh
