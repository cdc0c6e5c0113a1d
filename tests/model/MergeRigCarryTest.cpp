// What of the dragged part's pose, pins and keys a merge keeps
// (MergeRigCarry): rotations of bones that are the same bones after the
// merge, on their new ids (the dragged root's folded into the bones leaving
// it); pins of surviving joints; keys at the union of
// both parts' key times, each part's animation unchanged at its own keys.
#include "ModelTestSupport.h"
#include "model/MergeRigCarry.h"

namespace rigmesh::model::test {
namespace {

Eigen::Quaterniond turn(double angle, const Vec3& axis) {
    return Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
}

// A chain a - b - c along x, rooted at a.
struct Chain {
    Skeleton skeleton;
    JointId a, b, c;
};

Chain chain(const Vec3& from) {
    Chain out;
    out.a = out.skeleton.addJoint(from);
    out.b = out.skeleton.addJoint(from + Vec3(1, 0, 0));
    out.c = out.skeleton.addJoint(from + Vec3(2, 0, 0));
    out.skeleton.addBone(out.a, out.b);
    out.skeleton.addBone(out.b, out.c);
    return out;
}

PartNode nodeOf(const Skeleton& skeleton) {
    auto part = std::make_shared<Part>();
    part->skeleton = skeleton;
    PartNode node;
    node.name = QStringLiteral("arm");
    node.part = part;
    return node;
}

// The target: a body bone t0 - t1 (t1 a leaf); the dragged chain joins at t1
// by `dragged`'s joint `at`, as a snap does (the joint becomes t1).
struct Merge {
    PartNode target, dragged;
    std::map<JointId, JointId> joints;  // dragged -> merged
};

Merge snapAt(bool atRoot) {
    Merge m;
    Skeleton body;
    const JointId t0 = body.addJoint(Vec3(-1, 0, 0));
    const JointId t1 = body.addJoint(Vec3(0, 0, 0));
    body.addBone(t0, t1);
    const Chain arm = chain(Vec3(0, 0, 0));
    m.dragged = nodeOf(arm.skeleton);
    Skeleton merged = body;
    const JointId at = atRoot ? arm.a : arm.c;
    for (const Joint& joint : arm.skeleton.joints())
        m.joints[joint.id] = joint.id == at ? t1 : merged.addJoint(joint.position);
    for (const Bone& bone : arm.skeleton.bones())
        merged.addBone(m.joints.at(bone.head), m.joints.at(bone.tail));
    merged.reorient();
    m.target = nodeOf(merged);
    return m;
}

TEST(MergeRigCarry, RotationsOfAChainSnappedByItsRootAreKeptOnTheNewIds) {
    Merge m = snapAt(true);
    const Chain arm = chain(Vec3(0, 0, 0));
    m.dragged.pose.setRotation(arm.a, turn(0.3, Vec3::UnitZ()));
    m.dragged.pose.setRotation(arm.b, turn(-0.5, Vec3::UnitY()));
    m.dragged.pinnedJoints = {arm.c};
    const DraggedRigCarry carried =
        carryDraggedRig(m.target, m.dragged, m.joints, Eigen::Quaterniond::Identity());
    // The root's whole-arm rotation now lives in the bone leaving it (the
    // root ends the body's bone after the snap); bit for bit: same axes.
    EXPECT_FALSE(carried.pose.rotations.contains(m.joints.at(arm.a)));
    EXPECT_EQ(carried.pose.rotation(m.joints.at(arm.b)).coeffs(),
              (turn(0.3, Vec3::UnitZ()) * turn(-0.5, Vec3::UnitY())).normalized().coeffs());
    EXPECT_EQ(carried.pinned, (std::set<JointId>{m.joints.at(arm.c)}));
    EXPECT_EQ(carried.keptRotations, (std::vector<JointId>{arm.a, arm.b}));
    EXPECT_TRUE(carried.droppedRotations.empty());
    EXPECT_EQ(carried.describe(QStringLiteral("arm")),
              QStringLiteral("from arm: kept the rotations of 2 joint(s), 1 pin(s)"));
}

// Snapped by its far end, the chain hangs the other way: each joint would
// turn other joints than before, so every rotation is dropped and named.
TEST(MergeRigCarry, RotationsOfAReversedChainAreDroppedAndNamed) {
    Merge m = snapAt(false);
    const Chain arm = chain(Vec3(0, 0, 0));
    m.dragged.pose.setRotation(arm.a, turn(0.3, Vec3::UnitZ()));
    m.dragged.pose.setRotation(arm.b, turn(0.2, Vec3::UnitZ()));
    m.dragged.pose.setRotation(arm.c, Eigen::Quaterniond::Identity());  // at rest: nothing lost
    m.dragged.pose.rootTranslation = Vec3(0, 1, 0);
    const DraggedRigCarry carried =
        carryDraggedRig(m.target, m.dragged, m.joints, Eigen::Quaterniond::Identity());
    EXPECT_TRUE(carried.pose.rotations.empty());
    EXPECT_EQ(carried.droppedRotations, (std::vector<JointId>{arm.a, arm.b}));
    EXPECT_TRUE(carried.droppedRootOffset);
    EXPECT_EQ(carried.describe(QStringLiteral("arm")),
              QStringLiteral("from arm: dropped the rotations of joint(s) 0, 1 (in the merged "
                             "skeleton they would turn other bones), its root offset"));
}

// A dragged part placed at another angle: its rotations are about its own
// axes, so they turn with the placement into the merged part's axes.
TEST(MergeRigCarry, RotationsFollowTheDraggedPartsPlacement) {
    Merge m = snapAt(true);
    const Chain arm = chain(Vec3(0, 0, 0));
    const Eigen::Quaterniond q = turn(0.4, Vec3::UnitX());
    m.dragged.pose.setRotation(arm.b, q);
    const Eigen::Quaterniond placement = turn(M_PI / 2, Vec3::UnitZ());
    const DraggedRigCarry carried = carryDraggedRig(m.target, m.dragged, m.joints, placement);
    const Eigen::Quaterniond got = carried.pose.rotation(m.joints.at(arm.b));
    // About the dragged part's x, which is the merged part's y.
    EXPECT_NEAR(got.angularDistance(turn(0.4, Vec3::UnitY())), 0.0, 1e-12);
}

TEST(MergeRigCarry, KeysAreMergedAtTheUnionOfTimesKeepingEachPartsKeys) {
    Merge m = snapAt(true);
    const Chain arm = chain(Vec3(0, 0, 0));
    const JointId t0 = m.target.part->skeleton.root();
    Pose bodyKey;
    bodyKey.setRotation(t0, turn(0.25, Vec3::UnitZ()));
    m.target.clip.setKey(0.5, bodyKey);
    for (double time : {0.0, 1.0}) {
        Pose armKey;
        armKey.setRotation(arm.b, turn(time + 0.1, Vec3::UnitY()));
        m.dragged.clip.setKey(time, armKey);
    }
    const DraggedRigCarry carried =
        carryDraggedRig(m.target, m.dragged, m.joints, Eigen::Quaterniond::Identity());
    EXPECT_EQ(carried.clip.keyTimes(), (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_EQ(carried.mergedKeys, 2);
    for (double time : {0.0, 0.5, 1.0}) {
        const Pose key = carried.clip.key(time);
        // Each part's animation, as it was, at every key.
        EXPECT_EQ(key.rotation(t0).coeffs(), m.target.clip.evaluate(time).rotation(t0).coeffs());
        EXPECT_EQ(key.rotation(m.joints.at(arm.b)).coeffs(),
                  m.dragged.clip.evaluate(time).rotation(arm.b).coeffs());
    }
}

TEST(MergeRigCarry, NothingToCarrySaysNothing) {
    const Merge m = snapAt(true);
    const DraggedRigCarry carried =
        carryDraggedRig(m.target, m.dragged, m.joints, Eigen::Quaterniond::Identity());
    EXPECT_TRUE(carried.describe(QStringLiteral("arm")).isEmpty());
    EXPECT_TRUE(carried.clip.keys().empty());
}

}  // namespace
}  // namespace rigmesh::model::test
