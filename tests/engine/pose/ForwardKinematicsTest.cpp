#include <random>

#include "PoseTestSupport.h"
#include "base/Error.h"
#include "pose/ForwardKinematics.h"

namespace rigmesh::posetest {
namespace {

// Posed bone lengths match rest lengths to this fraction of the rest length.
constexpr double kLengthRelative = 1e-9;
// Absolute tolerance for hand-computed positions on unit-sized chains.
constexpr double kPositionTolerance = 1e-12;
constexpr int kRandomPoses = 50;

class ForwardKinematicsOnParts : public ::testing::TestWithParam<std::string> {};

TEST_P(ForwardKinematicsOnParts, RestPoseGivesIdentityTransformsAndRestPositionsExactly) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PosedSkeleton posed = forwardKinematics(skeleton, restPose(skeleton));
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        EXPECT_TRUE(posed.jointTransforms[j].isIdentity());
        EXPECT_EQ(posed.jointPositions[j], skeleton.joints()[j].position);
    }
    for (const RigidTransform& t : posed.boneTransforms)
        EXPECT_TRUE(t.isIdentity());
    // An empty pose means the rest pose too.
    const PosedSkeleton empty = forwardKinematics(skeleton, Pose{});
    for (int j = 0; j < skeleton.jointCount(); ++j)
        EXPECT_EQ(empty.jointPositions[j], skeleton.joints()[j].position);
}

TEST_P(ForwardKinematicsOnParts, RandomPosesKeepBoneLengths) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    std::mt19937 rng(7);
    for (int k = 0; k < kRandomPoses; ++k) {
        const Pose pose = randomPose(skeleton, rng, M_PI, 10.0);
        const std::vector<double> lengths = posedBoneLengths(skeleton, pose);
        for (int b = 0; b < skeleton.boneCount(); ++b) {
            const double rest = skeleton.boneLength(skeleton.bones()[b].id);
            EXPECT_NEAR(lengths[b], rest, kLengthRelative * rest);
        }
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, ForwardKinematicsOnParts,
                         ::testing::Values("tube", "y_branch", "biped"),
                         testsupport::sketchTestName);

TEST(ForwardKinematics, RotatingABoneTurnsItAndItsDescendantsAboutItsHead) {
    const Skeleton chain = straightChain(3, 1.0);  // joints at x = 0, 1, 2, 3
    Pose pose;
    // The bone ending at joint 2 (from joint 1) turns about joint 1.
    pose.setRotation(2, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())));
    const PosedSkeleton posed = forwardKinematics(chain, pose);
    EXPECT_TRUE(posed.jointPositions[0].isApprox(Vec3(0, 0, 0)));
    EXPECT_NEAR((posed.jointPositions[1] - Vec3(1, 0, 0)).norm(), 0, kPositionTolerance);
    EXPECT_NEAR((posed.jointPositions[2] - Vec3(1, 1, 0)).norm(), 0, kPositionTolerance);
    EXPECT_NEAR((posed.jointPositions[3] - Vec3(1, 2, 0)).norm(), 0, kPositionTolerance);
    // The first bone stays; the turned bone and the one below it turned.
    EXPECT_TRUE(posed.boneTransforms[0].isIdentity());
    EXPECT_NEAR(posed.boneTransforms[1].rotation.angularDistance(pose.rotation(2)), 0,
                kPositionTolerance);
    EXPECT_NEAR(posed.boneTransforms[2].rotation.angularDistance(pose.rotation(2)), 0,
                kPositionTolerance);
}

TEST(ForwardKinematics, BoneRotationsComposeDownTheChain) {
    const Skeleton chain = straightChain(2, 1.0);
    Pose pose;
    const Eigen::Quaterniond quarter(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
    pose.setRotation(1, quarter);
    pose.setRotation(2, quarter);
    pose.rootTranslation = Vec3(0, 0, 5);
    const PosedSkeleton posed = forwardKinematics(chain, pose);
    // The first bone turned to +y, then the next a further quarter turn to -x.
    EXPECT_NEAR((posed.jointPositions[1] - Vec3(0, 1, 5)).norm(), 0, kPositionTolerance);
    EXPECT_NEAR((posed.jointPositions[2] - Vec3(-1, 1, 5)).norm(), 0, kPositionTolerance);
}

TEST(ForwardKinematics, TheRootsRotationTurnsTheWholeSkeletonAboutTheRoot) {
    const Skeleton chain = straightChain(2, 1.0);
    Pose pose;
    pose.setRotation(0, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())));
    pose.setRotation(2, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())));
    const PosedSkeleton posed = forwardKinematics(chain, pose);
    EXPECT_EQ(posed.jointPositions[0], Vec3::Zero());
    EXPECT_NEAR((posed.jointPositions[1] - Vec3(0, 1, 0)).norm(), 0, kPositionTolerance);
    EXPECT_NEAR((posed.jointPositions[2] - Vec3(-1, 1, 0)).norm(), 0, kPositionTolerance);
}

// A Y: root 0 at the origin, junction 1 at (1, 0, 0), branches to 2 and 3.
Skeleton ySkeleton() {
    Skeleton y;
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 1, 0), Vec3(2, -1, 0)})
        y.addJoint(p);
    y.addBone(0, 1);
    y.addBone(1, 2);
    y.addBone(1, 3);
    return y;
}

TEST(ForwardKinematics, BonesLeavingAJunctionTurnIndependently) {
    const Skeleton y = ySkeleton();
    Pose pose;
    pose.setRotation(2, Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ())));
    const PosedSkeleton posed = forwardKinematics(y, pose);
    // Bone 1 -> 2 turned a quarter about the junction: (1, 1) -> (-1, 1).
    EXPECT_NEAR((posed.jointPositions[2] - Vec3(0, 1, 0)).norm(), 0, kPositionTolerance);
    // Its sibling and the trunk did not move at all.
    EXPECT_EQ(posed.jointPositions[3], Vec3(2, -1, 0));
    EXPECT_EQ(posed.jointPositions[1], Vec3(1, 0, 0));
    EXPECT_TRUE(posed.boneTransforms[0].isIdentity());
    EXPECT_TRUE(posed.boneTransforms[2].isIdentity());
}

TEST(ForwardKinematics, BoneDirectionInTheSkeletonDoesNotMatter) {
    // The same chain with its bones stored tail to head, rooted at joint 0.
    Skeleton reversed;
    for (int i = 0; i <= 3; ++i)
        reversed.addJoint(Vec3(i, 0, 0));
    for (JointId i = 0; i < 3; ++i)
        reversed.addBone(i + 1, i);
    const Skeleton forward = straightChain(3, 1.0);
    std::mt19937 rng(3);
    const Pose pose = randomPose(forward, rng, M_PI);
    const PosedSkeleton a = forwardKinematics(forward, pose);
    const PosedSkeleton b = forwardKinematics(reversed, pose);
    for (int j = 0; j < 4; ++j)
        EXPECT_EQ(a.jointPositions[j], b.jointPositions[j]);
}

TEST(ForwardKinematics, UnnormalisedRotationsAreNormalised) {
    const Skeleton chain = straightChain(2, 1.0);
    Pose pose;
    pose.setRotation(1, Eigen::Quaterniond(2, 0, 0, 2));  // 90 degrees about z, scaled
    EXPECT_NEAR(posedBoneLengths(chain, pose)[0], 1.0, kLengthRelative);
}

TEST(ForwardKinematics, NonFiniteOrZeroRotationIsAnError) {
    const Skeleton chain = straightChain(2, 1.0);
    Pose zero;
    zero.setRotation(1, Eigen::Quaterniond(0, 0, 0, 0));
    EXPECT_THROW(forwardKinematics(chain, zero), Error);
    Pose nan;
    nan.setRotation(1, Eigen::Quaterniond(std::nan(""), 0, 0, 0));
    EXPECT_THROW(forwardKinematics(chain, nan), Error);
    Pose far;
    far.rootTranslation = Vec3(INFINITY, 0, 0);
    EXPECT_THROW(forwardKinematics(chain, far), Error);
}

}  // namespace
}  // namespace rigmesh::posetest
