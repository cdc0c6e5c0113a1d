// Posing skeletons with disconnected bones (rig/Skeleton.h attachments), as
// imported rigs have them: a disconnected child's head follows its parent
// bone's frame (Blender's disconnected bones), FK, IK across such a joint,
// and skinning.
#include <gtest/gtest.h>

#include <random>

#include "PoseTestSupport.h"
#include "pose/ForwardKinematics.h"
#include "pose/InverseKinematics.h"
#include "pose/Skinning.h"

namespace rigmesh::posetest {
namespace {

// A spine (root 0 -> 1 -> 2, up +y) with an arm whose shoulder (3) sits off
// the spine's top, hanging from the upper spine bone: upper arm 3 -> 4,
// forearm 4 -> 5 along +x.
struct Torso {
    Skeleton skeleton;
    JointId root, middle, top, shoulder, elbow, hand;
    BoneId lower, upper, upperArm, forearm;
};

Torso torso() {
    Torso t;
    Skeleton& s = t.skeleton;
    t.root = s.addJoint(Vec3(0, 0, 0));
    t.middle = s.addJoint(Vec3(0, 1, 0));
    t.top = s.addJoint(Vec3(0, 2, 0));
    t.shoulder = s.addJoint(Vec3(0.5, 1.8, 0));
    t.elbow = s.addJoint(Vec3(1.5, 1.8, 0));
    t.hand = s.addJoint(Vec3(2.5, 1.8, 0));
    t.lower = s.addBone(t.root, t.middle);
    t.upper = s.addBone(t.middle, t.top);
    t.upperArm = s.addBone(t.shoulder, t.elbow);
    t.forearm = s.addBone(t.elbow, t.hand);
    s.attach(t.shoulder, t.upper);
    return t;
}

Vec3 at(const Skeleton& s, const PosedSkeleton& posed, JointId joint) {
    return posed.jointPositions[s.indexOfJoint(joint)];
}

TEST(DisconnectedPose, TheRestPoseIsTheIdentity) {
    const Torso t = torso();
    const PosedSkeleton posed = forwardKinematics(t.skeleton, restPose(t.skeleton));
    for (const Joint& joint : t.skeleton.joints())
        EXPECT_EQ(at(t.skeleton, posed, joint.id), joint.position);
}

TEST(DisconnectedPose, AChildsHeadFollowsItsParentBonesFrame) {
    const Torso t = torso();
    Pose pose;
    // The upper spine bone bends 90 degrees about z (toward -x) at its head.
    const Eigen::Quaterniond bend(Eigen::AngleAxisd(M_PI / 2, Vec3::UnitZ()));
    pose.setRotation(t.top, bend);
    const PosedSkeleton posed = forwardKinematics(t.skeleton, pose);
    const Vec3 pivot = t.skeleton.joint(t.middle).position;
    for (JointId joint : {t.shoulder, t.elbow, t.hand}) {
        const Vec3 rest = t.skeleton.joint(joint).position;
        EXPECT_LE((at(t.skeleton, posed, joint) - (pivot + bend * (rest - pivot))).norm(), 1e-12);
    }
    // The arm's bones turn with it: their transform is the spine bone's.
    const int upperArm = t.skeleton.indexOfBone(t.upperArm);
    EXPECT_TRUE(posed.boneTransforms[upperArm].rotation.isApprox(bend, 1e-12));
}

TEST(DisconnectedPose, TheChainRootsRotationTurnsItsChainAboutItsHead) {
    const Torso t = torso();
    Pose pose;
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Vec3::UnitY()));
    pose.setRotation(t.shoulder, turn);
    const PosedSkeleton posed = forwardKinematics(t.skeleton, pose);
    const Vec3 head = t.skeleton.joint(t.shoulder).position;
    EXPECT_EQ(at(t.skeleton, posed, t.shoulder), head);
    const Vec3 hand = t.skeleton.joint(t.hand).position;
    EXPECT_LE((at(t.skeleton, posed, t.hand) - (head + turn * (hand - head))).norm(), 1e-12);
    EXPECT_EQ(at(t.skeleton, posed, t.top), t.skeleton.joint(t.top).position);
}

TEST(DisconnectedPose, AFurtherRootChainFollowsTheRoot) {
    Torso t = torso();
    t.skeleton.attach(t.shoulder, kNoBone);
    Pose pose;
    pose.rootTranslation = Vec3(1, 2, 3);
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.4, Vec3::UnitX()));
    pose.setRotation(t.root, turn);
    const PosedSkeleton posed = forwardKinematics(t.skeleton, pose);
    for (const Joint& joint : t.skeleton.joints())
        EXPECT_LE(
            (at(t.skeleton, posed, joint.id) - (Vec3(1, 2, 3) + turn * joint.position)).norm(),
            1e-12);
}

TEST(DisconnectedPose, BodyReachIkCrossesTheDisconnectedJoint) {
    const Torso t = torso();
    const Vec3 target(1.2, 2.6, 0.4);
    IkOptions options;
    const IkResult result = dragJoint(t.skeleton, Pose{}, t.hand, target, {}, options);
    EXPECT_TRUE(result.reached) << result.distanceToTarget;
    const PosedSkeleton posed = forwardKinematics(t.skeleton, result.pose);
    EXPECT_LE((at(t.skeleton, posed, t.hand) - target).norm(), 1e-6);
    // The spine turned too (the chain crossed the shoulder into it), the
    // shoulder rigidly with it, and every bone kept its length.
    EXPECT_TRUE(result.pose.rotations.contains(t.top) || result.pose.rotations.contains(t.middle));
    EXPECT_EQ(result.chain.front(), t.root);
    EXPECT_EQ(result.chain.back(), t.hand);
    EXPECT_EQ(std::count(result.chain.begin(), result.chain.end(), t.top), 0)
        << "the spine's tail is no pivot: the rigid link runs from the spine's head";
    for (const Bone& bone : t.skeleton.bones())
        EXPECT_NEAR((at(t.skeleton, posed, bone.tail) - at(t.skeleton, posed, bone.head)).norm(),
                    t.skeleton.boneLength(bone.id), 1e-9);
    const Vec3 spineTop = at(t.skeleton, posed, t.top),
               spineMiddle = at(t.skeleton, posed, t.middle);
    const Vec3 shoulder = at(t.skeleton, posed, t.shoulder);
    const int upper = t.skeleton.indexOfBone(t.upper);
    const RigidTransform& frame = posed.boneTransforms[upper];
    EXPECT_LE((frame.apply(t.skeleton.joint(t.shoulder).position) - shoulder).norm(), 1e-12);
    EXPECT_LE((frame.apply(t.skeleton.joint(t.top).position) - spineTop).norm(), 1e-12);
    EXPECT_LE((frame.apply(t.skeleton.joint(t.middle).position) - spineMiddle).norm(), 1e-12);
}

TEST(DisconnectedPose, LimbReachStopsAtAChainRootWhoseParentCarriesMore) {
    Torso t = torso();
    // A head bone on the spine's tail: the spine bone carries more than the arm.
    const JointId crown = t.skeleton.addJoint(Vec3(0, 2.5, 0));
    t.skeleton.addBone(t.top, crown);
    IkOptions limb;
    limb.stopAtJunctions = true;
    const Vec3 target(1.5, 1.0, 0.5);
    const IkResult result = dragJoint(t.skeleton, Pose{}, t.hand, target, {}, limb);
    EXPECT_EQ(result.chain.front(), t.shoulder);
    EXPECT_FALSE(result.pose.rotations.contains(t.top));
    const PosedSkeleton posed = forwardKinematics(t.skeleton, result.pose);
    EXPECT_EQ(at(t.skeleton, posed, crown), t.skeleton.joint(crown).position);
    EXPECT_EQ(at(t.skeleton, posed, t.shoulder), t.skeleton.joint(t.shoulder).position);

    // Without the head the arm is the spine bone's only load: the chain
    // crosses into it.
    const Torso alone = torso();
    const IkResult crossing = dragJoint(alone.skeleton, Pose{}, alone.hand, target, {}, limb);
    EXPECT_NE(crossing.chain.front(), alone.shoulder);
}

TEST(DisconnectedPose, AChainHangingAtItsParentsHeadDragsWithoutNaN) {
    Torso t = torso();
    t.skeleton.setJointPosition(t.shoulder, t.skeleton.joint(t.middle).position);
    t.skeleton.setJointPosition(t.elbow, Vec3(1, 1, 0));
    t.skeleton.setJointPosition(t.hand, Vec3(2, 1, 0));
    const IkResult result = dragJoint(t.skeleton, Pose{}, t.hand, Vec3(1.5, 1.8, 0.3));
    EXPECT_TRUE(result.pose.isFinite());
    EXPECT_TRUE(result.reached) << result.distanceToTarget;
}

TEST(DisconnectedPose, DraggingAFurtherRootChainsRootMovesNothing) {
    Torso t = torso();
    t.skeleton.attach(t.shoulder, kNoBone);
    const IkResult result = dragJoint(t.skeleton, Pose{}, t.shoulder, Vec3(3, 3, 3));
    EXPECT_TRUE(result.chain.empty());
    EXPECT_TRUE(result.pose.rotations.empty());
}

TEST(DisconnectedPose, SkinningFollowsTheDisconnectedBones) {
    const Torso t = torso();
    // One vertex on each arm bone and one on the spine.
    TriMesh mesh;
    mesh.vertices = {Vec3(1.0, 1.9, 0), Vec3(2.0, 1.9, 0), Vec3(0.1, 1.5, 0)};
    mesh.faces = {{0, 1, 2}};
    SkinWeightsById weights;
    weights.perVertex = {{{t.upperArm, 1.0}}, {{t.forearm, 1.0}}, {{t.upper, 1.0}}};
    Pose pose;
    pose.setRotation(t.top, Eigen::Quaterniond(Eigen::AngleAxisd(0.5, Vec3::UnitZ())));
    pose.setRotation(t.elbow, Eigen::Quaterniond(Eigen::AngleAxisd(0.8, Vec3::UnitY())));
    const PosedSkeleton posed = forwardKinematics(t.skeleton, pose);
    const SkinningTransforms transforms(t.skeleton, posed.boneTransforms);
    for (SkinningMethod method : {SkinningMethod::LinearBlend, SkinningMethod::DualQuaternion}) {
        const SkinnedVertices skinned =
            skinVertices(mesh.vertices, {}, weights.perVertex, transforms, SkinningOptions{method});
        for (int v = 0; v < 3; ++v) {
            const int bone = t.skeleton.indexOfBone(weights.perVertex[v].front().first);
            EXPECT_LE(
                (skinned.positions[v] - posed.boneTransforms[bone].apply(mesh.vertices[v])).norm(),
                1e-12);
        }
    }
}

}  // namespace
}  // namespace rigmesh::posetest
