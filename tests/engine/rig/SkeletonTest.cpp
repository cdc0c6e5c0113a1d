#include "rig/Skeleton.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "ProblemMentions.h"
#include "base/Error.h"

namespace rigmesh {
namespace {

using testsupport::mentions;

// A chain of `count` joints along x, one unit apart, bones in order.
Skeleton chain(int count) {
    Skeleton s;
    for (int i = 0; i < count; ++i) {
        s.addJoint(Vec3(i, 0, 0));
    }
    for (int i = 0; i + 1 < count; ++i) {
        s.addBone(s.joints()[i].id, s.joints()[i + 1].id);
    }
    return s;
}

TEST(Skeleton, ChainIsAValidTree) {
    const Skeleton s = chain(4);
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(s.root(), s.joints().front().id);
    EXPECT_DOUBLE_EQ(s.boneLength(s.bones()[1].id), 1.0);
}

TEST(Skeleton, SingleJointIsAValidTreeButEmptySkeletonIsNot) {
    Skeleton s;
    EXPECT_FALSE(s.validate().empty());
    s.addJoint(Vec3::Zero());
    EXPECT_TRUE(s.validate().empty());
}

TEST(Skeleton, ValidateDetectsCycle) {
    Skeleton s = chain(3);
    s.addBone(s.joints()[2].id, s.joints()[0].id);
    const auto problems = s.validate();
    EXPECT_TRUE(mentions(problems, "cycle"));
    EXPECT_FALSE(mentions(problems, "not connected"));
}

TEST(Skeleton, ValidateDetectsParallelBonesAsCycle) {
    Skeleton s = chain(2);
    s.addBone(s.joints()[1].id, s.joints()[0].id);
    EXPECT_TRUE(mentions(s.validate(), "cycle"));
}

TEST(Skeleton, ValidateDetectsDisconnectedParts) {
    Skeleton s = chain(3);
    const JointId a = s.addJoint(Vec3(0, 5, 0));
    const JointId b = s.addJoint(Vec3(1, 5, 0));
    s.addBone(a, b);
    const auto problems = s.validate();
    EXPECT_TRUE(mentions(problems, "not connected"));
    EXPECT_TRUE(mentions(problems, "2 separate components"));
    EXPECT_FALSE(mentions(problems, "cycle"));
}

TEST(Skeleton, ValidateDetectsIsolatedJoint) {
    Skeleton s = chain(3);
    s.addJoint(Vec3(9, 9, 9));
    EXPECT_TRUE(mentions(s.validate(), "not connected"));
}

TEST(Skeleton, ValidateDetectsZeroLengthBoneRelativeToSize) {
    Skeleton s;
    const JointId a = s.addJoint(Vec3(0, 0, 0));
    const JointId b = s.addJoint(Vec3(1000, 0, 0));
    const JointId c = s.addJoint(Vec3(1000, 1e-10, 0));
    s.addBone(a, b);
    const BoneId tiny = s.addBone(b, c);
    const auto problems = s.validate();
    ASSERT_EQ(problems.size(), 1u);
    EXPECT_TRUE(mentions(problems, "Bone " + std::to_string(tiny) + " has zero length"));

    // The same short bone is fine in a skeleton of its own size.
    Skeleton small;
    small.addBone(small.addJoint(Vec3(0, 0, 0)), small.addJoint(Vec3(0, 1e-10, 0)));
    EXPECT_TRUE(small.validate().empty());
}

TEST(Skeleton, ValidateDetectsDanglingIds) {
    const Skeleton s =
        Skeleton::restore({{0, Vec3(0, 0, 0)}, {1, Vec3(1, 0, 0)}}, {{0, 0, 1}, {1, 1, 7}}, 0);
    EXPECT_TRUE(mentions(s.validate(), "joint 7, which does not exist"));

    const Skeleton badRoot = Skeleton::restore({{0, Vec3(0, 0, 0)}}, {}, 3);
    EXPECT_TRUE(mentions(badRoot.validate(), "root"));
}

TEST(Skeleton, RestoreKeepsIdsAndContinuesCounters) {
    Skeleton s = Skeleton::restore({{4, Vec3(0, 0, 0)}, {9, Vec3(1, 0, 0)}}, {{6, 4, 9}}, 9);
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(s.root(), 9u);
    EXPECT_EQ(s.addJoint(Vec3(2, 0, 0)), 10u);
    EXPECT_EQ(s.addBone(9, 10), 7u);
}

TEST(Skeleton, AddBoneRejectsUnknownJointsAndSelfLoops) {
    Skeleton s = chain(2);
    EXPECT_THROW(s.addBone(0, 42), Error);
    EXPECT_THROW(s.addBone(1, 1), Error);
    EXPECT_THROW(s.joint(42), Error);
    EXPECT_THROW(s.removeBone(42), Error);
}

TEST(Skeleton, IdsSurviveRemoveBone) {
    Skeleton s = chain(4);
    const std::vector<Joint> jointsBefore = s.joints();
    const BoneId first = s.bones()[0].id;
    const BoneId last = s.bones()[2].id;
    s.removeBone(s.bones()[1].id);
    ASSERT_EQ(s.boneCount(), 2);
    EXPECT_EQ(s.bones()[0].id, first);
    EXPECT_EQ(s.bones()[1].id, last);
    EXPECT_EQ(s.indexOfBone(last), 1);
    EXPECT_EQ(s.bone(last).head, jointsBefore[2].id);
    ASSERT_EQ(s.jointCount(), 4);
    for (const Joint& j : jointsBefore) {
        EXPECT_EQ(s.joint(j.id).position, j.position);
    }
    // A new bone gets a fresh id, never a removed one.
    const BoneId fresh = s.addBone(jointsBefore[1].id, jointsBefore[2].id);
    EXPECT_EQ(fresh, 3u);
    EXPECT_TRUE(s.validate().empty());
}

TEST(Skeleton, RemoveJointRemovesItsBonesAndKeepsOtherIds) {
    Skeleton s = chain(4);
    const JointId middle = s.joints()[1].id;
    s.removeJoint(middle);
    EXPECT_FALSE(s.hasJoint(middle));
    EXPECT_EQ(s.boneCount(), 1);
    EXPECT_EQ(s.bones()[0].id, 2u);
    EXPECT_EQ(s.indexOfJoint(3), 2);
    EXPECT_EQ(s.addJoint(Vec3::Zero()), 4u);
}

TEST(Skeleton, RemovingTheRootPicksAnotherRoot) {
    Skeleton s = chain(3);
    s.removeJoint(s.root());
    EXPECT_EQ(s.root(), 1u);
    s.removeJoint(1);
    s.removeJoint(2);
    EXPECT_EQ(s.root(), kNoJoint);
}

TEST(Skeleton, CollapseBoneKeepsHeadIdAndRewiresBones) {
    // 0 - 1 - 2 - 3 with an extra branch 2 - 4.
    Skeleton s = chain(4);
    const JointId branch = s.addJoint(Vec3(2, 1, 0));
    const BoneId branchBone = s.addBone(2, branch);
    const BoneId middle = s.bones()[1].id;  // 1 -> 2
    const BoneId last = s.bones()[2].id;    // 2 -> 3
    s.collapseBone(middle, Vec3(1.5, 0, 0));

    EXPECT_FALSE(s.hasBone(middle));
    EXPECT_FALSE(s.hasJoint(2));
    EXPECT_EQ(s.joint(1).position, Vec3(1.5, 0, 0));
    EXPECT_EQ(s.bone(last).head, 1u);
    EXPECT_EQ(s.bone(last).tail, 3u);
    EXPECT_EQ(s.bone(branchBone).head, 1u);
    EXPECT_EQ(s.bone(branchBone).tail, branch);
    EXPECT_EQ(s.degree(1), 3);
    EXPECT_TRUE(s.validate().empty());
    EXPECT_EQ(s.addJoint(Vec3::Zero()), 5u);
    EXPECT_EQ(s.addBone(3, 5), 4u);  // bones 0..3 existed; 1 is gone, never reused
}

TEST(Skeleton, CollapsingABoneWhoseTailIsTheRootMovesTheRootToTheSurvivor) {
    Skeleton s;
    const JointId j0 = s.addJoint(Vec3(0, 0, 0));  // the root
    const JointId j1 = s.addJoint(Vec3(1, 0, 0));
    const JointId j2 = s.addJoint(Vec3(2, 0, 0));
    const BoneId toRoot = s.addBone(j1, j0);
    s.addBone(j1, j2);
    ASSERT_EQ(s.root(), j0);
    s.collapseBone(toRoot, Vec3(0.5, 0, 0));
    EXPECT_EQ(s.root(), j1);
    EXPECT_FALSE(s.hasJoint(j0));
    EXPECT_TRUE(s.validate().empty());
    EXPECT_TRUE(s.isOrientedFromRoot());
}

TEST(Skeleton, ReorientMakesHeadsPointToTheRoot) {
    // A star around joint 0 built with mixed directions, rooted at a leaf.
    Skeleton s;
    const JointId centre = s.addJoint(Vec3(0, 0, 0));
    const JointId a = s.addJoint(Vec3(1, 0, 0));
    const JointId b = s.addJoint(Vec3(0, 1, 0));
    const JointId c = s.addJoint(Vec3(0, 0, 1));
    const JointId d = s.addJoint(Vec3(0, 0, 2));
    s.addBone(a, centre);
    s.addBone(centre, b);
    s.addBone(c, centre);
    s.addBone(d, c);
    s.setRoot(b);
    EXPECT_FALSE(s.isOrientedFromRoot());
    s.reorient();
    EXPECT_TRUE(s.isOrientedFromRoot());
    EXPECT_EQ(s.bones()[1].head, b);
    EXPECT_EQ(s.bones()[1].tail, centre);
    EXPECT_EQ(s.bones()[0].head, centre);
    EXPECT_EQ(s.bones()[2].head, centre);
    EXPECT_EQ(s.bones()[3].head, c);
    EXPECT_EQ(s.bones()[3].tail, d);

    EXPECT_FALSE(s.parentBone(s.bones()[1].id).has_value());
    EXPECT_EQ(s.parentBone(s.bones()[0].id), s.bones()[1].id);
    EXPECT_EQ(s.parentBone(s.bones()[3].id), s.bones()[2].id);
    EXPECT_EQ(s.childrenOf(centre), (std::vector<BoneId>{0, 2}));
    EXPECT_TRUE(s.childrenOf(d).empty());
    EXPECT_EQ(s.degree(centre), 3);

    // Parents come before children.
    const auto order = s.bonesInHierarchyOrder();
    ASSERT_EQ(order.size(), 4u);
    EXPECT_EQ(order.front(), s.bones()[1].id);
    const auto at = [&](BoneId id) { return std::find(order.begin(), order.end(), id); };
    EXPECT_LT(at(s.bones()[2].id), at(s.bones()[3].id));
}

TEST(Skeleton, CentralRootOfChainIsItsMiddleJoint) {
    const Skeleton s = chain(5);
    EXPECT_EQ(chooseCentralRoot(s), s.joints()[2].id);
}

TEST(Skeleton, CentralRootUsesBoneLengthsNotJointCounts) {
    // 0 --10-- 1 -1- 2 -1- 3 -1- 4: the centre by length is joint 1.
    Skeleton s;
    const double xs[] = {0, 10, 11, 12, 13};
    for (double x : xs) {
        s.addJoint(Vec3(x, 0, 0));
    }
    for (JointId i = 0; i < 4; ++i) {
        s.addBone(i, i + 1);
    }
    EXPECT_EQ(chooseCentralRoot(s), 1u);
}

TEST(Skeleton, CentralRootOfYIsItsBranchingJoint) {
    // A Y whose stem is built first, so the branching joint is not joint 0.
    Skeleton s;
    const JointId foot = s.addJoint(Vec3(0, -2, 0));
    const JointId hip = s.addJoint(Vec3(0, -1, 0));
    const JointId fork = s.addJoint(Vec3(0, 0, 0));
    const JointId left = s.addJoint(Vec3(-1.4, 1.4, 0));
    const JointId right = s.addJoint(Vec3(1.4, 1.4, 0));
    s.addBone(foot, hip);
    s.addBone(hip, fork);
    s.addBone(fork, left);
    s.addBone(fork, right);
    EXPECT_EQ(chooseCentralRoot(s), fork);
}

TEST(Skeleton, CentralRootPrefersBranchingJointOnTies) {
    // a(-1) - fork(0) - m(1) - b(2) along x, plus c at (0, 1) on the fork.
    // Both fork and m have eccentricity 2, m comes first, the fork has degree 3.
    Skeleton s;
    const JointId m = s.addJoint(Vec3(1, 0, 0));
    const JointId fork = s.addJoint(Vec3(0, 0, 0));
    const JointId a = s.addJoint(Vec3(-1, 0, 0));
    const JointId b = s.addJoint(Vec3(2, 0, 0));
    const JointId c = s.addJoint(Vec3(0, 1, 0));
    s.addBone(fork, a);
    s.addBone(fork, m);
    s.addBone(m, b);
    s.addBone(fork, c);
    // fork: max(1, 2, 1) = 2; m: max(2, 1, 2) = 2 and m comes first.
    EXPECT_EQ(chooseCentralRoot(s), fork);
}

TEST(Skeleton, CentralRootOfStarIsItsCentre) {
    Skeleton s;
    const JointId tip = s.addJoint(Vec3(3, 0, 0));
    const JointId centre = s.addJoint(Vec3(0, 0, 0));
    s.addBone(centre, tip);
    for (int k = 0; k < 5; ++k) {
        const double angle = 1.0 + k;
        s.addBone(centre, s.addJoint(Vec3(3 * std::cos(angle), 3 * std::sin(angle), 0)));
    }
    EXPECT_EQ(chooseCentralRoot(s), centre);
}

TEST(Skeleton, CentralRootOfDisconnectedSkeletonLiesInLargestComponent) {
    Skeleton s;
    s.addBone(s.addJoint(Vec3(0, 5, 0)), s.addJoint(Vec3(1, 5, 0)));
    const JointId first = s.addJoint(Vec3(0, 0, 0));
    const JointId middle = s.addJoint(Vec3(1, 0, 0));
    const JointId last = s.addJoint(Vec3(2, 0, 0));
    s.addBone(first, middle);
    s.addBone(middle, last);
    EXPECT_EQ(chooseCentralRoot(s), middle);
    EXPECT_THROW(chooseCentralRoot(Skeleton()), Error);
}

}  // namespace
}  // namespace rigmesh
