// Poses of format version 1 (one rotation per joint turning every bone
// leaving it) convert to per-bone poses with the very same bone transforms.
#include <random>

#include "PoseTestSupport.h"
#include "pose/Clip.h"
#include "pose/LegacyPose.h"

namespace rigmesh::posetest {
namespace {

// Forward kinematics as version 1 defined it, written out here as the
// reference: T_root = translate(t) * rotate(q_root about rest_root),
// T_child = T_parent * rotate(q_child about rest_child), and a bone moves
// with the joint nearer the root.
std::vector<RigidTransform> versionOneBoneTransforms(const PoseHierarchy& h, const Pose& pose) {
    std::vector<RigidTransform> joint(h.jointCount(), RigidTransform::identity());
    for (int j : h.parentFirstOrder()) {
        const RigidTransform local = RigidTransform::rotationAbout(
            pose.rotation(h.jointId(j)).normalized(), h.restPosition(j));
        if (j == h.root()) {
            joint[j] = local;
            joint[j].translation += pose.rootTranslation;
        } else {
            joint[j] = joint[h.parent(j)] * local;
        }
    }
    std::vector<RigidTransform> bones;
    for (int b = 0; b < h.boneCount(); ++b)
        bones.push_back(joint[h.boneHeadJoint(b)]);
    return bones;
}

void expectIdenticalTransforms(const std::vector<RigidTransform>& a,
                               const std::vector<RigidTransform>& b, const std::string& what) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) {
        EXPECT_EQ(a[i].rotation.coeffs(), b[i].rotation.coeffs()) << what << " bone " << i;
        EXPECT_EQ(a[i].translation, b[i].translation) << what << " bone " << i;
    }
}

class LegacyPoses : public ::testing::TestWithParam<std::string> {};

TEST_P(LegacyPoses, ConvertedPosesGiveBitIdenticalBoneTransforms) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PoseHierarchy h(skeleton);
    std::mt19937 rng(23);
    for (int k = 0; k < 20; ++k) {
        const Pose legacy = randomPose(skeleton, rng, M_PI, 2.0);
        const Pose converted = poseFromJointRotations(h, legacy);
        EXPECT_FALSE(converted.rotations.contains(skeleton.root()));
        expectIdenticalTransforms(forwardKinematics(h, converted).boneTransforms,
                                  versionOneBoneTransforms(h, legacy), GetParam());
    }
}

TEST_P(LegacyPoses, ConvertedClipsEvaluateToTheSameBoneTransforms) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PoseHierarchy h(skeleton);
    std::mt19937 rng(29);
    for (const Interpolation interpolation : {Interpolation::Linear, Interpolation::Smooth}) {
        Clip legacy(24.0);
        legacy.interpolation = interpolation;
        for (double t : {0.0, 0.5, 1.25, 2.0})
            legacy.setKey(t, randomPose(skeleton, rng, 2.0, 1.0));
        const Clip converted = clipFromJointRotations(h, legacy);
        EXPECT_EQ(converted.keyTimes(), legacy.keyTimes());
        EXPECT_EQ(converted.interpolation, interpolation);
        for (double t = -0.2; t < 2.3; t += 0.13)
            expectIdenticalTransforms(forwardKinematics(h, converted.evaluate(t)).boneTransforms,
                                      versionOneBoneTransforms(h, legacy.evaluate(t)),
                                      "t = " + std::to_string(t));
    }
}

TEST_P(LegacyPoses, VersionOneRotationsOfSomeJointsSetOnAConvertedPoseAreExact) {
    const Skeleton& skeleton = sharedPart(GetParam()).skeleton;
    const PoseHierarchy h(skeleton);
    std::mt19937 rng(31);
    Pose legacy = randomPose(skeleton, rng, 1.0, 0.5);
    Pose converted = poseFromJointRotations(h, legacy);
    // A recipe step of version 1 sets a junction, the root and a leaf.
    std::map<JointId, Eigen::Quaterniond> step;
    for (int j = 0; j < h.jointCount(); ++j)
        if (j == h.root() || h.children(j).size() != 1)
            step[h.jointId(j)] = randomRotation(rng, 1.0);
    for (const auto& [joint, q] : step)
        legacy.setRotation(joint, q);
    setJointRotations(h, step, converted);
    expectIdenticalTransforms(forwardKinematics(h, converted).boneTransforms,
                              versionOneBoneTransforms(h, legacy), GetParam());
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, LegacyPoses,
                         ::testing::Values("tube", "y_branch", "biped", "quadruped"));

}  // namespace
}  // namespace rigmesh::posetest
