// Two limbs a small gap apart are one on a proxy, which bridges the gap,
// and get one chain; the mesh has them apart, so the chain becomes two and
// each limb's vertices follow only its own bones (autorig/FusedLimbs).
#include <gtest/gtest.h>

#include <array>

#include "autorig/FusedLimbs.h"
#include "autorig/SkeletonFromCurve.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

// A tube along z from `bottom` to `top`, its axis through (x, 0).
TriMesh tube(double x, double radius, double bottom, double top) {
    TriMesh mesh = makeCylinderTube(16, 16, radius, top - bottom);
    for (Vec3& v : mesh.vertices)
        v += Vec3(x, 0.0, 0.5 * (top + bottom));
    return mesh;
}

TriMesh joined(const TriMesh& a, const TriMesh& b) {
    TriMesh mesh = a;
    const int offset = mesh.vertexCount();
    mesh.vertices.insert(mesh.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const auto& [p, q, r] : b.faces)
        mesh.faces.push_back({p + offset, q + offset, r + offset});
    return mesh;
}

// The joint at the head of the bone that ends at `joint` (none at the root).
JointId parentOf(const Skeleton& skeleton, JointId joint) {
    for (BoneId bone : skeleton.bonesAt(joint))
        if (skeleton.bone(bone).tail == joint)
            return skeleton.bone(bone).head;
    return kNoJoint;
}

// A junction with two short arms and one leg chain down the middle of
// the proxy, as the curve skeleton of a proxy around two legs gives it.
Skeleton figureWithOneLegChain() {
    Skeleton skeleton;
    const JointId junction = skeleton.addJoint(Vec3(0, 0, 2));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(1, 0, 2.8)));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(-1, 0, 2.8)));
    const JointId knee = skeleton.addJoint(Vec3(0, 0, -4.5));
    skeleton.addBone(junction, knee);
    skeleton.addBone(knee, skeleton.addJoint(Vec3(0, 0, -9.5)));
    skeleton.setRoot(junction);
    skeleton.reorient();
    return skeleton;
}

TEST(FusedLimbs, AChainThroughTwoLimbsAGapApartBecomesOneChainPerLimb) {
    // Legs of radius 0.5 with a gap of 0.2 between them; the proxy is one
    // tube around both.
    const TriMesh legs = joined(tube(-0.6, 0.5, -10, 0), tube(0.6, 0.5, -10, 0));
    const TriMesh proxy = tube(0.0, 1.3, -10.3, 3.3);
    Skeleton skeleton = figureWithOneLegChain();
    const FusedLimbsReport report = splitFusedLimbs(skeleton, legs, proxy);
    EXPECT_EQ(report.chainsSplit, 1);
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_EQ(leafCount(skeleton), 4);  // two arms, two legs
    int left = 0, right = 0;
    for (const Joint& joint : skeleton.joints()) {
        if (skeleton.degree(joint.id) != 1 || joint.position.z() > 0.0)
            continue;
        // Each leg's tip in the middle of its own leg's end.
        EXPECT_NEAR(std::abs(joint.position.x()), 0.6, 0.1);
        EXPECT_NEAR(joint.position.y(), 0.0, 0.1);
        (joint.position.x() < 0.0 ? left : right) += 1;
    }
    EXPECT_EQ(left, 1);
    EXPECT_EQ(right, 1);
}

TEST(FusedLimbs, EachLimbsVerticesKeepOnlyItsOwnBonesWeights) {
    const TriMesh legs = joined(tube(-0.6, 0.5, -10, 0), tube(0.6, 0.5, -10, 0));
    const TriMesh proxy = tube(0.0, 1.3, -10.3, 3.3);
    Skeleton skeleton = figureWithOneLegChain();
    const FusedLimbsReport report = splitFusedLimbs(skeleton, legs, proxy);
    ASSERT_EQ(report.chainsSplit, 1);
    // The proxy's heat shared between the legs: half to each leg's last bone.
    BoneId leftBone = kNoBone, rightBone = kNoBone;
    for (const Bone& bone : skeleton.bones())
        if (skeleton.degree(bone.tail) == 1 && skeleton.joint(bone.tail).position.z() < 0.0)
            (skeleton.joint(bone.tail).position.x() < 0.0 ? leftBone : rightBone) = bone.id;
    ASSERT_NE(leftBone, kNoBone);
    ASSERT_NE(rightBone, kNoBone);
    WeightsById weights(legs.vertices.size(), {{leftBone, 0.5}, {rightBone, 0.5}});
    EXPECT_GT(separateFusedLimbWeights(legs, skeleton, report, weights), 0);
    for (int v = 0; v < legs.vertexCount(); ++v) {
        if ((legs.vertices[v] - report.splits.front().point).dot(report.splits.front().normal) <= 0)
            continue;  // above where the legs part
        ASSERT_EQ(weights[v].size(), 1u);
        EXPECT_EQ(weights[v].front().first, legs.vertices[v].x() < 0.0 ? leftBone : rightBone);
        EXPECT_DOUBLE_EQ(weights[v].front().second, 1.0);
    }
}

TEST(FusedLimbs, AChainThroughOneLimbStaysAsItIs) {
    const TriMesh leg = tube(0.0, 1.1, -10, 0);
    const TriMesh proxy = tube(0.0, 1.3, -10.3, 3.3);
    Skeleton skeleton = figureWithOneLegChain();
    const Skeleton before = skeleton;
    EXPECT_EQ(splitFusedLimbs(skeleton, leg, proxy).chainsSplit, 0);
    ASSERT_EQ(skeleton.jointCount(), before.jointCount());
    ASSERT_EQ(skeleton.boneCount(), before.boneCount());
    for (int j = 0; j < skeleton.jointCount(); ++j) {
        EXPECT_EQ(skeleton.joints()[j].id, before.joints()[j].id);
        EXPECT_EQ(skeleton.joints()[j].position, before.joints()[j].position);
    }
    for (int b = 0; b < skeleton.boneCount(); ++b) {
        EXPECT_EQ(skeleton.bones()[b].head, before.bones()[b].head);
        EXPECT_EQ(skeleton.bones()[b].tail, before.bones()[b].tail);
    }
}

// Legs apart down to the knees and touching below: the proxy has each thigh
// apart and the shins as one (a loop thigh, shins, thigh, as sydney's of
// assimp-testmodels), and the curve skeleton's tree, cut at the far end of
// that loop, gives one chain down the left thigh and both shins, and the
// right thigh a chain ending at its knee.
TEST(FusedLimbs, AShinTheProxyJoinedToTheOtherShinContinuesItsOwnThighsChain) {
    const TriMesh legs = joined(tube(-0.6, 0.5, -10, 0), tube(0.6, 0.5, -10, 0));
    TriMesh proxy = joined(tube(-0.6, 0.55, -5.0, 2.5), tube(0.6, 0.55, -5.0, 2.5));
    proxy = joined(proxy, tube(0.0, 1.3, -10.3, -4.5));
    Skeleton skeleton;
    const JointId junction = skeleton.addJoint(Vec3(0, 0, 2));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(1, 0, 2.8)));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(-1, 0, 2.8)));
    const JointId leftHip = skeleton.addJoint(Vec3(-0.6, 0, 0));
    skeleton.addBone(junction, leftHip);
    const JointId leftKnee = skeleton.addJoint(Vec3(-0.6, 0, -4));
    skeleton.addBone(leftHip, leftKnee);
    const JointId shins = skeleton.addJoint(Vec3(-0.3, 0, -5));
    skeleton.addBone(leftKnee, shins);
    skeleton.addBone(shins, skeleton.addJoint(Vec3(0, 0, -9.5)));
    const JointId rightHip = skeleton.addJoint(Vec3(0.6, 0, 0));
    skeleton.addBone(junction, rightHip);
    const JointId rightKnee = skeleton.addJoint(Vec3(0.6, 0, -4.6));
    skeleton.addBone(rightHip, rightKnee);
    skeleton.setRoot(junction);
    skeleton.reorient();

    const FusedLimbsReport report = splitFusedLimbs(skeleton, legs, proxy);
    EXPECT_EQ(report.chainsSplit, 1);
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_EQ(leafCount(skeleton), 4);  // two arms, two legs
    EXPECT_EQ(skeleton.degree(rightKnee), 2) << "the right thigh's chain goes on down its shin";
    for (const Joint& joint : skeleton.joints()) {
        if (skeleton.degree(joint.id) != 1 || joint.position.z() > 0.0)
            continue;
        // Each foot in the middle of its own leg's end, reached from the
        // junction through its own hip.
        EXPECT_NEAR(std::abs(joint.position.x()), 0.6, 0.1);
        EXPECT_LT(joint.position.z(), -8.0);
        JointId up = joint.id;
        while (parentOf(skeleton, up) != kNoJoint && parentOf(skeleton, up) != junction)
            up = parentOf(skeleton, up);
        EXPECT_EQ(up, joint.position.x() < 0.0 ? leftHip : rightHip);
    }
}

// Legs fused from the crotch down with no hip junction of their own: the
// chain from the chest runs down the torso and both legs, so the limbs part
// low on it (past its first quarter), and no other chain ends near where
// they do. Both legs leave the parting joint (mrfixit of assimp-testmodels,
// its legs 1.4% of the diagonal apart).
TEST(FusedLimbs, LegsPartingLowOnAChainFromTheChestBothLeaveWhereTheyPart) {
    TriMesh mesh = joined(tube(-0.6, 0.5, -10, 0), tube(0.6, 0.5, -10, 0));
    mesh = joined(mesh, tube(0.0, 1.1, 0.0, 9.0));  // the torso
    const TriMesh proxy = tube(0.0, 1.3, -10.3, 10.0);
    Skeleton skeleton;
    const JointId chest = skeleton.addJoint(Vec3(0, 0, 8));
    skeleton.addBone(chest, skeleton.addJoint(Vec3(1, 0, 8.8)));
    skeleton.addBone(chest, skeleton.addJoint(Vec3(-1, 0, 8.8)));
    const JointId belly = skeleton.addJoint(Vec3(0, 0, 3));
    skeleton.addBone(chest, belly);
    const JointId knees = skeleton.addJoint(Vec3(0, 0, -4.5));
    skeleton.addBone(belly, knees);
    skeleton.addBone(knees, skeleton.addJoint(Vec3(0, 0, -9.5)));
    skeleton.setRoot(chest);
    skeleton.reorient();

    const FusedLimbsReport report = splitFusedLimbs(skeleton, mesh, proxy);
    EXPECT_EQ(report.chainsSplit, 1);
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_EQ(leafCount(skeleton), 4);  // two arms, two legs
    std::vector<JointId> feet;
    for (const Joint& joint : skeleton.joints())
        if (skeleton.degree(joint.id) == 1 && joint.position.z() < 0.0)
            feet.push_back(joint.id);
    ASSERT_EQ(feet.size(), 2u);
    // Up each leg to where it branches: the same joint, at the crotch.
    std::array<JointId, 2> parting{};
    for (int k = 0; k < 2; ++k) {
        EXPECT_NEAR(std::abs(skeleton.joint(feet[k]).position.x()), 0.6, 0.1);
        JointId up = parentOf(skeleton, feet[k]);
        while (up != kNoJoint && skeleton.degree(up) == 2)
            up = parentOf(skeleton, up);
        ASSERT_NE(up, kNoJoint);
        parting[k] = up;
    }
    EXPECT_EQ(parting[0], parting[1]);
    EXPECT_NE(parting[0], chest);
    EXPECT_NEAR(skeleton.joint(parting[0]).position.z(), 0.0, 1.5);
    EXPECT_LT(skeleton.joint(feet[0]).position.x() * skeleton.joint(feet[1]).position.x(), 0.0);
}

// Each leg has a chain of its own, but the proxy is one tube around both:
// a plane across either chain cuts the mesh in two outlines, the other one
// the other chain's leg. No chain is split (a third leg's chain would lie
// along one of them).
TEST(FusedLimbs, ALimbThatHasAChainOfItsOwnGetsNoSecondOne) {
    const TriMesh legs = joined(tube(-0.6, 0.5, -10, 0), tube(0.6, 0.5, -10, 0));
    const TriMesh proxy = tube(0.0, 1.3, -10.3, 3.3);
    Skeleton skeleton;
    const JointId junction = skeleton.addJoint(Vec3(0, 0, 2));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(1, 0, 2.8)));
    skeleton.addBone(junction, skeleton.addJoint(Vec3(-1, 0, 2.8)));
    for (double x : {-0.6, 0.6}) {
        const JointId hip = skeleton.addJoint(Vec3(x, 0, 0));
        skeleton.addBone(junction, hip);
        const JointId knee = skeleton.addJoint(Vec3(x, 0, -4.5));
        skeleton.addBone(hip, knee);
        skeleton.addBone(knee, skeleton.addJoint(Vec3(x, 0, -9.5)));
    }
    skeleton.setRoot(junction);
    skeleton.reorient();
    const Skeleton before = skeleton;

    EXPECT_EQ(splitFusedLimbs(skeleton, legs, proxy).chainsSplit, 0);
    EXPECT_EQ(leafCount(skeleton), 4);
    ASSERT_EQ(skeleton.jointCount(), before.jointCount());
    for (int j = 0; j < skeleton.jointCount(); ++j)
        EXPECT_EQ(skeleton.joints()[j].position, before.joints()[j].position);
}

}  // namespace
}  // namespace rigmesh
