#include <random>

#include "PoseTestSupport.h"
#include "base/Error.h"
#include "pose/Clip.h"

namespace rigmesh::posetest {
namespace {

constexpr double kFps = 24.0;
// Sampling step for continuity checks, and the largest rotation (radians) or
// translation change allowed per sample: well above the curves' speed times
// the step, far below any real jump.
constexpr double kSampleStep = 1e-4;
constexpr double kMaxAngleStepPerSample = 0.01;
constexpr double kMaxTranslationStepPerSample = 0.01;
constexpr JointId kJoints = 4;

Pose keyPose(std::mt19937& rng) {
    Pose pose;
    for (JointId j = 0; j < kJoints; ++j)
        pose.setRotation(j, randomRotation(rng, 2.5));
    std::uniform_real_distribution<double> offset(-1, 1);
    pose.rootTranslation = Vec3(offset(rng), offset(rng), offset(rng));
    return pose;
}

Clip randomClip(Interpolation interpolation, PlaybackMode mode) {
    std::mt19937 rng(29);
    Clip clip(kFps);
    clip.interpolation = interpolation;
    clip.mode = mode;
    for (double t : {0.0, 0.5, 1.25, 2.0, 2.5})
        clip.setKey(t, keyPose(rng));
    return clip;
}

double poseDistance(const Pose& a, const Pose& b) {
    double worst = (a.rootTranslation - b.rootTranslation).norm();
    for (JointId j = 0; j < kJoints; ++j)
        worst = std::max(worst, rotationAngle(a.rotation(j), b.rotation(j)));
    return worst;
}

std::string interpolationName(const ::testing::TestParamInfo<Interpolation>& param) {
    switch (param.param) {
        case Interpolation::Constant:
            return "Constant";
        case Interpolation::Linear:
            return "Linear";
        case Interpolation::Smooth:
            return "Smooth";
    }
    return "Unknown";
}

class ClipInterpolation : public ::testing::TestWithParam<Interpolation> {};

TEST_P(ClipInterpolation, IsExactAtKeys) {
    const Clip clip = randomClip(GetParam(), PlaybackMode::Hold);
    for (const auto& [time, key] : clip.keys()) {
        const Pose pose = clip.evaluate(time);
        EXPECT_EQ(pose.rootTranslation, key.rootTranslation);
        for (JointId j = 0; j < kJoints; ++j)
            EXPECT_EQ(pose.rotation(j).coeffs(), key.rotation(j).coeffs());
    }
}

TEST_P(ClipInterpolation, IsContinuousBetweenKeys) {
    const Clip clip = randomClip(GetParam(), PlaybackMode::Hold);
    Pose previous = clip.evaluate(-0.1);
    double worstAngle = 0, worstTranslation = 0;
    for (double t = -0.1; t <= 2.6; t += kSampleStep) {
        const Pose pose = clip.evaluate(t);
        ASSERT_TRUE(pose.isFinite());
        for (JointId j = 0; j < kJoints; ++j)
            worstAngle =
                std::max(worstAngle, rotationAngle(pose.rotation(j), previous.rotation(j)));
        worstTranslation =
            std::max(worstTranslation, (pose.rootTranslation - previous.rootTranslation).norm());
        previous = pose;
    }
    EXPECT_LT(worstAngle, kMaxAngleStepPerSample);
    EXPECT_LT(worstTranslation, kMaxTranslationStepPerSample);
}

TEST_P(ClipInterpolation, TakesTheShortWayBetweenOppositeHemispheres) {
    Clip clip;
    clip.interpolation = GetParam();
    Pose a, b;
    a.setRotation(0, Eigen::Quaterniond(Eigen::AngleAxisd(0.1, Vec3::UnitZ())));
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.3, Vec3::UnitZ()));
    b.setRotation(0, Eigen::Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()));  // same rotation
    clip.setKey(0, a);
    clip.setKey(1, b);
    clip.setKey(2, a);
    const Eigen::Quaterniond middle = clip.evaluate(0.5).rotation(0);
    EXPECT_NEAR(rotationAngle(middle, Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Vec3::UnitZ()))), 0,
                0.02);
}

INSTANTIATE_TEST_SUITE_P(Modes, ClipInterpolation,
                         ::testing::Values(Interpolation::Linear, Interpolation::Smooth),
                         interpolationName);

TEST(Clip, LinearInterpolationIsSlerpAndLerp) {
    Clip clip;
    Pose a, b;
    b.setRotation(1, Eigen::Quaterniond(Eigen::AngleAxisd(1.0, Vec3::UnitX())));
    b.rootTranslation = Vec3(2, 0, 0);
    clip.setKey(1.0, a);
    clip.setKey(3.0, b);
    const Pose quarter = clip.evaluate(1.5);
    EXPECT_NEAR(rotationAngle(quarter.rotation(1),
                              Eigen::Quaterniond(Eigen::AngleAxisd(0.25, Vec3::UnitX()))),
                0, 1e-12);
    EXPECT_NEAR((quarter.rootTranslation - Vec3(0.5, 0, 0)).norm(), 0, 1e-12);
}

TEST(Clip, HoldClampsToTheEndKeys) {
    const Clip clip = randomClip(Interpolation::Linear, PlaybackMode::Hold);
    EXPECT_EQ(poseDistance(clip.evaluate(-5.0), clip.keys().begin()->second), 0);
    EXPECT_EQ(poseDistance(clip.evaluate(99.0), clip.keys().rbegin()->second), 0);
}

TEST(Clip, LoopRepeatsTheSpanOfTheKeys) {
    for (Interpolation interpolation : {Interpolation::Linear, Interpolation::Smooth}) {
        const Clip clip = randomClip(interpolation, PlaybackMode::Loop);
        const double span = clip.duration();
        for (double t : {0.1, 0.7, 1.3, 2.2}) {
            EXPECT_LT(poseDistance(clip.evaluate(t + span), clip.evaluate(t)), 1e-9);
            EXPECT_LT(poseDistance(clip.evaluate(t - 3 * span), clip.evaluate(t)), 1e-9);
        }
        EXPECT_EQ(poseDistance(clip.evaluate(2.5), clip.keys().begin()->second), 0);
    }
}

TEST(Clip, PingPongPlaysTheSpanForwardsThenBackwards) {
    for (Interpolation interpolation :
         {Interpolation::Constant, Interpolation::Linear, Interpolation::Smooth}) {
        const Clip clip = randomClip(interpolation, PlaybackMode::PingPong);
        const double first = clip.keys().begin()->first, span = clip.duration();
        for (double u : {0.1, 0.7, 1.3, 2.2}) {
            const Pose forwards = clip.evaluate(first + u);
            // Mirrored about the last key, and periodic over twice the span.
            EXPECT_LT(poseDistance(clip.evaluate(first + 2 * span - u), forwards), 1e-9);
            EXPECT_LT(poseDistance(clip.evaluate(first + u + 2 * span), forwards), 1e-9);
            EXPECT_LT(poseDistance(clip.evaluate(first + u - 4 * span), forwards), 1e-9);
        }
        EXPECT_EQ(poseDistance(clip.evaluate(first + span), clip.keys().rbegin()->second), 0);
        EXPECT_EQ(poseDistance(clip.evaluate(first + 2 * span), clip.keys().begin()->second), 0);
    }
}

TEST(Clip, ConstantHoldsEachKeyUntilTheNext) {
    const Clip clip = randomClip(Interpolation::Constant, PlaybackMode::Hold);
    const std::vector<double> times = clip.keyTimes();
    for (std::size_t k = 0; k + 1 < times.size(); ++k) {
        const Pose& key = clip.keys().at(times[k]);
        EXPECT_EQ(poseDistance(clip.evaluate(times[k]), key), 0);
        EXPECT_EQ(poseDistance(clip.evaluate(0.5 * (times[k] + times[k + 1])), key), 0);
        EXPECT_EQ(poseDistance(clip.evaluate(times[k + 1] - 1e-9), key), 0);
        EXPECT_EQ(poseDistance(clip.evaluate(times[k + 1]), clip.keys().at(times[k + 1])), 0);
    }
}

TEST(Clip, KeysAreAddressedWithinHalfAFrame) {
    Clip clip(kFps);
    Pose a, b;
    b.rootTranslation = Vec3(1, 0, 0);
    clip.setKey(1.0, a);
    EXPECT_TRUE(clip.hasKey(1.0 + 0.4 / kFps));
    EXPECT_FALSE(clip.hasKey(1.0 + 0.6 / kFps));
    // Setting within half a frame replaces (and retimes) the key.
    clip.setKey(1.0 + 0.3 / kFps, b);
    EXPECT_EQ(clip.keyCount(), 1);
    EXPECT_EQ(clip.key(1.0).rootTranslation, b.rootTranslation);
    EXPECT_EQ(clip.keyTime(1.0), 1.0 + 0.3 / kFps);
    // A key a frame away is a new key.
    clip.setKey(1.0 + 1.3 / kFps, a);
    EXPECT_EQ(clip.keyCount(), 2);
    // A higher frame rate narrows the tolerance.
    clip.setFramesPerSecond(4 * kFps);
    EXPECT_FALSE(clip.hasKey(1.0 + 0.3 / kFps - 0.2 / kFps));
}

TEST(Clip, MoveAndRemoveKeys) {
    Clip clip(kFps);
    Pose a, b;
    b.rootTranslation = Vec3(0, 1, 0);
    clip.setKey(0.0, a);
    clip.setKey(1.0, b);
    clip.moveKey(1.0, 2.0);
    EXPECT_EQ(clip.keyTimes(), (std::vector<double>{0.0, 2.0}));
    EXPECT_EQ(clip.key(2.0).rootTranslation, b.rootTranslation);
    // Moving onto another key replaces it.
    clip.moveKey(2.0, 0.01);
    EXPECT_EQ(clip.keyTimes(), (std::vector<double>{0.01}));
    EXPECT_EQ(clip.key(0.0).rootTranslation, b.rootTranslation);
    clip.removeKey(0.0);
    EXPECT_EQ(clip.keyCount(), 0);
    EXPECT_THROW(clip.removeKey(0.0), Error);
    EXPECT_THROW(clip.moveKey(5.0, 6.0), Error);
}

TEST(Clip, BadInputIsAnError) {
    Clip clip;
    EXPECT_THROW(clip.evaluate(0.0), Error);
    EXPECT_THROW(clip.duration(), Error);
    clip.setKey(0.0, Pose{});
    EXPECT_THROW(clip.evaluate(std::nan("")), Error);
    EXPECT_THROW(clip.setKey(std::nan(""), Pose{}), Error);
    Pose bad;
    bad.setRotation(0, Eigen::Quaterniond(0, 0, 0, 0));
    EXPECT_THROW(clip.setKey(1.0, bad), Error);
    EXPECT_THROW(Clip(0.0), Error);
    EXPECT_THROW(clip.setFramesPerSecond(-1.0), Error);
    EXPECT_THROW(clip.key(5.0), Error);
}

TEST(Clip, SingleKeyHoldsEverywhere) {
    Clip clip;
    clip.mode = PlaybackMode::Loop;
    Pose a;
    a.rootTranslation = Vec3(1, 2, 3);
    clip.setKey(0.5, a);
    EXPECT_EQ(clip.evaluate(-3.0).rootTranslation, a.rootTranslation);
    EXPECT_EQ(clip.evaluate(7.0).rootTranslation, a.rootTranslation);
}

// Key times of 1e308 once reached a .glb as Infinity.
TEST(Clip, KeysBeyondTheLongestKeyTimeAreRefused) {
    Clip clip;
    EXPECT_THROW(clip.setKey(1e308, Pose{}), Error);
    EXPECT_THROW(clip.setKey(-2 * Clip::kLongestKeyTime, Pose{}), Error);
    clip.setKey(Clip::kLongestKeyTime, Pose{});
    EXPECT_THROW(clip.moveKey(Clip::kLongestKeyTime, 1e300), Error);
    EXPECT_EQ(clip.keyTimes(), (std::vector<double>{Clip::kLongestKeyTime}));
}

// Keys at -1 s, or keys moved below 0 s, reached glTF files as animation
// input times below zero (the validator's ACCESSOR_ANIMATION_INPUT_NEGATIVE).
TEST(Clip, KeysBeforeZeroAreRefused) {
    Clip clip;
    for (double time : {-1.0, -1e-9, -Clip::kLongestKeyTime}) {
        try {
            clip.setKey(time, Pose{});
            ADD_FAILURE() << "a key at " << time << " s was accepted";
        } catch (const Error& error) {
            EXPECT_EQ(error.message().id, MessageId::KeyTimeNegative) << error.what();
        }
        EXPECT_THROW(clip.insertExactKey(time, Pose{}), Error);
    }
    clip.setKey(0.0, Pose{});
    clip.setKey(0.25, Pose{});
    EXPECT_THROW(clip.moveKey(0.0, -0.25), Error);
    EXPECT_EQ(clip.keyTimes(), (std::vector<double>{0.0, 0.25})) << "nothing moved";
    // Playing before the first key is still fine: it holds or wraps.
    EXPECT_NO_THROW(clip.evaluate(-3.0));
}

}  // namespace
}  // namespace rigmesh::posetest
