#include "rig/DouglasPeucker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>

#include "base/Error.h"

namespace rigmesh {
namespace {

// Deterministic noise in [-amplitude, amplitude] (mt19937's output is portable).
class Noise {
  public:
    explicit Noise(double amplitude) : amplitude_(amplitude) {}
    double operator()() { return amplitude_ * (2.0 * engine_() / 4294967295.0 - 1.0); }

  private:
    double amplitude_;
    std::mt19937 engine_{20121128u};
};

// A sample at p whose chord is perpendicular to `direction`, halfWidth each side.
AxisSample sampleAt(const Vec2& p, const Vec2& direction, double halfWidth) {
    const Vec2 n = Vec2(-direction.y(), direction.x()).normalized();
    return {p, p + halfWidth * n, p - halfWidth * n};
}

// A straight axis along x in [0, 10] with noisy y and the given half-width.
std::vector<AxisSample> straightTube(int count, double noiseAmplitude,
                                     const std::function<double(double)>& halfWidth) {
    Noise noise(noiseAmplitude);
    std::vector<AxisSample> axis;
    for (int i = 0; i < count; ++i) {
        const double x = 10.0 * i / (count - 1);
        axis.push_back(sampleAt(Vec2(x, noise()), Vec2(1, 0), halfWidth(x)));
    }
    return axis;
}

// The paper's Fig. 4: a nearly straight axis, thickness changing abruptly at x = 5.
std::vector<AxisSample> fig4Tube() {
    return straightTube(200, 0.01, [](double x) { return x < 5.0 ? 1.0 : 0.4; });
}

// An L: along x from (0, 0) to (10, 0), then up to (10, 10), half-width 1.
std::vector<AxisSample> lTube() {
    std::vector<AxisSample> axis;
    for (int i = 0; i <= 100; ++i) {
        axis.push_back(sampleAt(Vec2(0.1 * i, 0), Vec2(1, 0), 1.0));
    }
    axis.back() = sampleAt(axis.back().point, Vec2(1, 1), 1.0);  // chord along the bisector
    for (int i = 1; i <= 100; ++i) {
        axis.push_back(sampleAt(Vec2(10, 0.1 * i), Vec2(0, 1), 1.0));
    }
    return axis;
}

std::vector<AxisSample> scaled(std::vector<AxisSample> axis, double factor) {
    for (AxisSample& s : axis) {
        s.point *= factor;
        s.chordA *= factor;
        s.chordB *= factor;
    }
    return axis;
}

bool hasInteriorIndexNear(const std::vector<AxisSample>& axis, const std::vector<int>& kept,
                          const Vec2& target, double radius) {
    for (std::size_t k = 1; k + 1 < kept.size(); ++k) {
        if ((axis[kept[k]].point - target).norm() < radius) {
            return true;
        }
    }
    return false;
}

TEST(DouglasPeucker, AbruptThicknessChangeOnStraightAxisStaysOneSegment) {
    const auto axis = fig4Tube();
    EXPECT_EQ(douglasPeucker(axis, 0.1), (std::vector<int>{0, 199}));
}

TEST(CylindricalDouglasPeucker, AbruptThicknessChangePutsJointAtTheKink) {
    const auto axis = fig4Tube();
    const auto kept = cylindricalDouglasPeucker(axis, 0.1);
    EXPECT_GT(kept.size(), 2u);
    EXPECT_TRUE(hasInteriorIndexNear(axis, kept, Vec2(5, 0), 0.5));
    // Joints are only placed at the kink, not along the noisy flat parts.
    for (std::size_t k = 1; k + 1 < kept.size(); ++k) {
        EXPECT_NEAR(axis[kept[k]].point.x(), 5.0, 0.5);
    }
}

TEST(DouglasPeucker, ConstantWidthStraightTubeIsOneSegment) {
    const auto axis = straightTube(150, 0.01, [](double) { return 0.8; });
    EXPECT_EQ(douglasPeucker(axis, 0.1), (std::vector<int>{0, 149}));
}

TEST(CylindricalDouglasPeucker, ConstantWidthStraightTubeIsOneSegment) {
    const auto axis = straightTube(150, 0.01, [](double) { return 0.8; });
    EXPECT_EQ(cylindricalDouglasPeucker(axis, 0.1), (std::vector<int>{0, 149}));
}

TEST(CylindricalDouglasPeucker, GradualTaperIsOneSegment) {
    // A cone is exactly one trapezoid: no joint however long it is.
    const auto axis = straightTube(150, 0.0, [](double x) { return 1.0 - 0.05 * x; });
    EXPECT_EQ(cylindricalDouglasPeucker(axis, 0.05), (std::vector<int>{0, 149}));
}

TEST(DouglasPeucker, BentAxisGetsJointAtTheBend) {
    const auto axis = lTube();
    const auto kept = douglasPeucker(axis, 0.1);
    EXPECT_EQ(kept.size(), 3u);
    EXPECT_TRUE(hasInteriorIndexNear(axis, kept, Vec2(10, 0), 0.5));
}

TEST(CylindricalDouglasPeucker, BentAxisGetsJointAtTheBend) {
    const auto axis = lTube();
    const auto kept = cylindricalDouglasPeucker(axis, 0.1);
    EXPECT_GE(kept.size(), 3u);
    EXPECT_TRUE(hasInteriorIndexNear(axis, kept, Vec2(10, 0), 0.5));
    for (std::size_t k = 1; k + 1 < kept.size(); ++k) {
        EXPECT_LT((axis[kept[k]].point - Vec2(10, 0)).norm(), 1.5);
    }
}

TEST(CylindricalDouglasPeucker, InvariantUnderScalingAxisAndThresholdTogether) {
    for (const auto& axis : {fig4Tube(), lTube()}) {
        for (double threshold : {0.02, 0.1, 0.3}) {
            const auto reference = cylindricalDouglasPeucker(axis, threshold);
            for (double factor : {0.01, 3.7, 250.0}) {
                EXPECT_EQ(cylindricalDouglasPeucker(scaled(axis, factor), threshold * factor),
                          reference)
                    << "threshold " << threshold << ", factor " << factor;
            }
        }
    }
}

TEST(CylindricalDouglasPeucker, SmallerThresholdKeepsAtLeastAsManyJoints) {
    const auto axis = fig4Tube();
    EXPECT_GE(cylindricalDouglasPeucker(axis, 0.02).size(),
              cylindricalDouglasPeucker(axis, 0.1).size());
}

TEST(CylindricalDouglasPeucker, TrapezoidHasEndChordsProjectedOntoTheNormalAsBases) {
    // Axis v_i v_j along x; the chord at v_i is tilted 45 degrees, length 2 * sqrt(2).
    const AxisSample first{Vec2(0, 0), Vec2(-1, 1), Vec2(1, -1)};
    const AxisSample last{Vec2(4, 0), Vec2(4, 0.5), Vec2(4, -0.5)};
    const CdpTrapezoid t = cdpTrapezoid(first, last);
    EXPECT_TRUE(t.a.isApprox(Vec2(0, 1)));
    EXPECT_TRUE(t.b.isApprox(Vec2(0, -1)));
    EXPECT_TRUE(t.c.isApprox(Vec2(4, -0.5)));
    EXPECT_TRUE(t.d.isApprox(Vec2(4, 0.5)));
}

TEST(CylindricalDouglasPeucker, ErrorIsSumOfSquaredDistancesOfChordEndsToSides) {
    // A rectangle of half-width 1 along x.
    const AxisSample first{Vec2(0, 0), Vec2(0, 1), Vec2(0, -1)};
    const AxisSample last{Vec2(10, 0), Vec2(10, 1), Vec2(10, -1)};
    const CdpTrapezoid t = cdpTrapezoid(first, last);
    // Chord ends 0.3 outside on top and 0.4 inside at the bottom; E and F in
    // either order give the same error.
    const AxisSample v{Vec2(5, 0.15), Vec2(5, 1.3), Vec2(5, -0.6)};
    EXPECT_NEAR(cdpError(t, v), 0.3 * 0.3 + 0.4 * 0.4, 1e-12);
    const AxisSample swapped{v.point, v.chordB, v.chordA};
    EXPECT_NEAR(cdpError(t, swapped), 0.3 * 0.3 + 0.4 * 0.4, 1e-12);
    // A sample matching the rectangle has no error.
    EXPECT_NEAR(cdpError(t, AxisSample{Vec2(3, 0), Vec2(3, 1), Vec2(3, -1)}), 0.0, 1e-12);
}

TEST(CylindricalDouglasPeucker, AxisDeviationAloneIsCaptured) {
    // Constant width, axis bumped sideways by 0.5 in the middle: the chord
    // ends move with it, so CDP splits just as DP does.
    std::vector<AxisSample> axis;
    for (int i = 0; i <= 100; ++i) {
        const double x = 0.1 * i;
        const double y = 0.5 * std::exp(-(x - 5) * (x - 5));
        axis.push_back(sampleAt(Vec2(x, y), Vec2(1, 0), 1.0));
    }
    EXPECT_GT(douglasPeucker(axis, 0.1).size(), 2u);
    const auto kept = cylindricalDouglasPeucker(axis, 0.1);
    EXPECT_GT(kept.size(), 2u);
}

TEST(DouglasPeucker, ShortAxesKeepEverySample) {
    EXPECT_TRUE(douglasPeucker({}, 0.1).empty());
    EXPECT_TRUE(cylindricalDouglasPeucker({}, 0.1).empty());
    const std::vector<AxisSample> one{sampleAt(Vec2(0, 0), Vec2(1, 0), 1)};
    EXPECT_EQ(douglasPeucker(one, 0.1), (std::vector<int>{0}));
    EXPECT_EQ(cylindricalDouglasPeucker(one, 0.1), (std::vector<int>{0}));
    const std::vector<AxisSample> two{one[0], sampleAt(Vec2(1, 0), Vec2(1, 0), 1)};
    EXPECT_EQ(douglasPeucker(two, 0.1), (std::vector<int>{0, 1}));
    EXPECT_EQ(cylindricalDouglasPeucker(two, 0.1), (std::vector<int>{0, 1}));
}

TEST(DouglasPeucker, ClosedAxisWithCoincidentEndsIsSplit) {
    // First and last samples coincide: the degenerate segment must not hide the loop.
    std::vector<AxisSample> axis;
    for (int i = 0; i <= 60; ++i) {
        const double angle = 2.0 * std::numbers::pi * i / 60;
        const Vec2 p(3 * std::cos(angle), 3 * std::sin(angle));
        axis.push_back(sampleAt(p, Vec2(-p.y(), p.x()), 0.5));
    }
    axis.back() = axis.front();
    EXPECT_GT(douglasPeucker(axis, 0.1).size(), 2u);
    EXPECT_GT(cylindricalDouglasPeucker(axis, 0.1).size(), 2u);
}

TEST(DouglasPeucker, RejectsNegativeOrNonFiniteThreshold) {
    const auto axis = fig4Tube();
    EXPECT_THROW(douglasPeucker(axis, -1.0), std::logic_error);
    EXPECT_THROW(cylindricalDouglasPeucker(axis, std::nan("")), std::logic_error);
}

}  // namespace
}  // namespace rigmesh
