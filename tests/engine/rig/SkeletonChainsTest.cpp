// Skeletons with disconnected bones (Skeleton.h): chains attached to a
// parent bone or hanging from no bone, as imported rigs have them.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ProblemMentions.h"
#include "base/Error.h"
#include "rig/Skeleton.h"

namespace rigmesh {
namespace {

using testsupport::mentions;

// A spine (root 0 -> 1 -> 2) and a thigh whose head (3) sits beside the
// spine's root, hanging from the first spine bone, with a shin below it.
struct Hips {
    Skeleton skeleton;
    JointId root, middle, top, hip, knee, foot;
    BoneId lower, upper, thigh, shin;
};

Hips hips() {
    Hips h;
    Skeleton& s = h.skeleton;
    h.root = s.addJoint(Vec3(0, 0, 0));
    h.middle = s.addJoint(Vec3(0, 1, 0));
    h.top = s.addJoint(Vec3(0, 2, 0));
    h.hip = s.addJoint(Vec3(0.3, 0, 0));
    h.knee = s.addJoint(Vec3(0.3, -1, 0));
    h.foot = s.addJoint(Vec3(0.3, -2, 0));
    h.lower = s.addBone(h.root, h.middle);
    h.upper = s.addBone(h.middle, h.top);
    h.thigh = s.addBone(h.hip, h.knee);
    h.shin = s.addBone(h.knee, h.foot);
    s.attach(h.hip, h.lower);
    return h;
}

TEST(SkeletonChains, AChainHangingFromABoneIsValid) {
    const Hips h = hips();
    EXPECT_TRUE(h.skeleton.validate().empty());
    EXPECT_FALSE(h.skeleton.isConnectedTree());
    EXPECT_EQ(h.skeleton.parentBone(h.thigh), h.lower);
    EXPECT_FALSE(h.skeleton.isConnected(h.thigh));
    EXPECT_TRUE(h.skeleton.isConnected(h.shin));
    EXPECT_TRUE(h.skeleton.isConnected(h.upper));
    EXPECT_FALSE(h.skeleton.isConnected(h.lower));  // a root bone
    EXPECT_EQ(h.skeleton.attachedTo(h.lower), std::vector<JointId>{h.hip});
}

TEST(SkeletonChains, AChainHangingFromNothingIsNotConnected) {
    Hips h = hips();
    h.skeleton.detach(h.hip);
    const auto problems = h.skeleton.validate();
    EXPECT_TRUE(mentions(problems, "not connected"));
    EXPECT_TRUE(mentions(problems, "2 separate components"));
}

TEST(SkeletonChains, AFurtherRootChainIsValid) {
    Hips h = hips();
    h.skeleton.attach(h.hip, kNoBone);
    EXPECT_TRUE(h.skeleton.validate().empty());
    EXPECT_EQ(h.skeleton.parentBone(h.thigh), std::nullopt);
}

TEST(SkeletonChains, BadAttachmentsAreNamed) {
    Hips own = hips();
    own.skeleton.attach(own.hip, own.shin);
    EXPECT_TRUE(mentions(own.skeleton.validate(), "hangs from a bone of its own chain"));

    Hips twice = hips();
    twice.skeleton.attach(twice.knee, twice.lower);
    EXPECT_TRUE(mentions(twice.skeleton.validate(), "both hang from bones but are in one chain"));

    Hips connected = hips();
    connected.skeleton.attach(connected.middle, connected.lower);
    EXPECT_TRUE(
        mentions(connected.skeleton.validate(), "hangs from a bone but is connected to the root"));

    // Two chains hanging from each other.
    Hips loop = hips();
    Skeleton& s = loop.skeleton;
    const JointId a = s.addJoint(Vec3(2, 0, 0)), b = s.addJoint(Vec3(2, 1, 0));
    const BoneId ab = s.addBone(a, b);
    s.attach(a, loop.thigh);
    s.attach(loop.hip, ab);
    EXPECT_TRUE(mentions(s.validate(), "hangs from chains that hang from it"));

    EXPECT_THROW(s.attach(s.root(), loop.lower), Error);
    EXPECT_THROW(s.attach(a, 99), Error);
}

TEST(SkeletonChains, ReorientTurnsEachChainAwayFromItsRoot) {
    Hips h = hips();
    Skeleton s = Skeleton::restore(h.skeleton.joints(),
                                   {{h.lower, h.middle, h.root},
                                    {h.upper, h.top, h.middle},
                                    {h.thigh, h.knee, h.hip},
                                    {h.shin, h.foot, h.knee}},
                                   h.root, h.skeleton.attachments());
    EXPECT_FALSE(s.isOrientedFromRoot());
    s.reorient();
    EXPECT_TRUE(s.isOrientedFromRoot());
    EXPECT_EQ(s.bone(h.thigh).head, h.hip);
    EXPECT_EQ(s.bone(h.shin).head, h.knee);
    EXPECT_TRUE(s.validate().empty());
}

TEST(SkeletonChains, HierarchyOrderPutsAChainAfterTheBoneItHangsFrom) {
    const Hips h = hips();
    const std::vector<BoneId> order = h.skeleton.bonesInHierarchyOrder();
    ASSERT_EQ(order.size(), 4u);
    auto at = [&](BoneId b) { return std::find(order.begin(), order.end(), b) - order.begin(); };
    EXPECT_LT(at(h.lower), at(h.thigh));
    EXPECT_LT(at(h.thigh), at(h.shin));
    EXPECT_LT(at(h.lower), at(h.upper));
}

TEST(SkeletonChains, RemovingOrCollapsingTheParentBoneKeepsTheChainHanging) {
    Hips removed = hips();
    removed.skeleton.attach(removed.hip, removed.upper);
    removed.skeleton.removeBone(removed.upper);
    EXPECT_EQ(removed.skeleton.attachments().at(removed.hip), removed.lower);

    Hips collapsed = hips();
    collapsed.skeleton.attach(collapsed.hip, collapsed.upper);
    collapsed.skeleton.collapseBone(collapsed.upper, Vec3(0, 1.5, 0));
    EXPECT_EQ(collapsed.skeleton.attachments().at(collapsed.hip), collapsed.lower);
    EXPECT_TRUE(collapsed.skeleton.validate().empty());

    Hips root = hips();
    root.skeleton.removeBone(root.lower);
    EXPECT_EQ(root.skeleton.attachments().at(root.hip), kNoBone);
}

TEST(SkeletonChains, SplittingAParentBoneKeepsTheChainOnTheNearerHalf) {
    Hips near = hips();  // the hip beside the bone's head: the first half
    near.skeleton.splitBone(near.lower, Vec3(0, 0.5, 0));
    EXPECT_EQ(near.skeleton.attachments().at(near.hip), near.lower);
    EXPECT_TRUE(near.skeleton.validate().empty());

    Hips far = hips();
    far.skeleton.setJointPosition(far.hip, Vec3(0.3, 0.9, 0));
    const JointId middle = far.skeleton.splitBone(far.lower, Vec3(0, 0.5, 0));
    BoneId second = kNoBone;
    for (BoneId b : far.skeleton.childrenOf(middle))
        second = b;
    EXPECT_EQ(far.skeleton.attachments().at(far.hip), second);
    EXPECT_TRUE(far.skeleton.validate().empty());
}

TEST(SkeletonChains, MergingAChainRootIntoAJointConnectsIt) {
    Hips h = hips();
    h.skeleton.mergeJoints(h.root, h.hip);
    EXPECT_TRUE(h.skeleton.isConnectedTree());
    EXPECT_TRUE(h.skeleton.validate().empty());
    EXPECT_TRUE(h.skeleton.isConnected(h.thigh) == false);  // a root bone now
    EXPECT_EQ(h.skeleton.bone(h.thigh).head, h.root);
}

}  // namespace
}  // namespace rigmesh
