// One shortest bone for every edit that makes bones (rig/ShortBones.h): a
// cut crossing a bone within it of a joint snaps to the joint, a piece left
// with only a shorter bone is refused with the lengths, bone splits stop at
// it, and a delete that would leave a neighbour shorter is refused.
#include <gtest/gtest.h>

#include <functional>

#include "SharedSketchPart.h"
#include "base/Error.h"
#include "cut/BoneEdits.h"
#include "cut/CutPart.h"
#include "rig/ShortBones.h"

namespace rigmesh {
namespace {

// Every bone of `part` at least `minimum` long.
void expectNoShortBone(const Part& part, double minimum, const std::string& what) {
    for (const Bone& bone : part.skeleton.bones())
        EXPECT_GE(part.skeleton.boneLength(bone.id), minimum)
            << what << ": bone " << bone.id << " is " << part.skeleton.boneLength(bone.id)
            << " long";
}

// A joint of degree one and the bone ending there.
std::pair<JointId, BoneId> aLeaf(const Part& part) {
    for (const Joint& joint : part.skeleton.joints())
        if (part.skeleton.degree(joint.id) == 1)
            return {joint.id, part.skeleton.bonesAt(joint.id).front()};
    ADD_FAILURE() << "no leaf joint";
    return {kNoJoint, 0};
}

Error errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "no error";
    return Error(std::string("none"));
}

TEST(ShortBones, ACutBesideTheRootJointSnapsToItInsteadOfMakingTinyBones) {
    // A plane 2.3e-5 from the star's central joint split every arm bone
    // there, leaving bones 2.3e-5 to 1.5e-4 long that led 175-185 vertices.
    const Part& star = testsupport::sharedSketchPart("star");
    const double minimum = minimumBoneLength(star.mesh);
    CutRequest request;
    request.normal = Vec3(1.0, 0.3, 0.0).normalized();
    request.point = star.skeleton.joint(star.skeleton.root()).position + 2.3e-5 * request.normal;
    const CutResult result = cutPart(star, request);
    for (int k = 0; k < 2; ++k) {
        const Part& piece = result.pieces[k];
        EXPECT_TRUE(piece.validateSolid().empty());
        expectNoShortBone(piece, minimum, "piece " + std::to_string(k));
        // The joint the crossings snapped to is in both pieces.
        EXPECT_TRUE(piece.skeleton.hasJoint(star.skeleton.root())) << "piece " << k;
    }
    EXPECT_EQ(result.pieces[0].skeleton.boneCount() + result.pieces[1].skeleton.boneCount(),
              star.skeleton.boneCount())
        << "no bone was split";
}

TEST(ShortBones, ACutJustBelowATipIsRefusedWithTheLengths) {
    // A cut 2.2e-4 below a tip gave a 107-vertex cap whose only bone was
    // 2.2e-4 long (importers drop such bones).
    const Part& star = testsupport::sharedSketchPart("star");
    const auto [tip, bone] = aLeaf(star);
    const Bone& b = star.skeleton.bone(bone);
    const JointId inner = b.head == tip ? b.tail : b.head;
    const Vec3 tipAt = star.skeleton.joint(tip).position;
    const Vec3 along = (tipAt - star.skeleton.joint(inner).position).normalized();
    CutRequest request;
    request.normal = along;
    request.point = tipAt - 2.2e-4 * along;
    const Error error = errorOf([&] { cutPart(star, request); });
    EXPECT_EQ(error.message().id, MessageId::CutPieceBoneTooShort) << error.what();
    ASSERT_EQ(error.message().args.size(), 2u);
    EXPECT_NEAR(std::stod(error.message().args[0]), 2.2e-4, 1e-6) << error.what();
    EXPECT_NEAR(std::stod(error.message().args[1]), minimumBoneLength(star.mesh),
                1e-3 * minimumBoneLength(star.mesh));

    // Three shortest bones below the tip, the cap keeps a bone that long.
    const double minimum = minimumBoneLength(star.mesh);
    request.point = tipAt - 3.0 * minimum * along;
    const CutResult result = cutPart(star, request);
    for (int k = 0; k < 2; ++k)
        expectNoShortBone(result.pieces[k], minimum, "piece " + std::to_string(k));
}

TEST(ShortBones, SplittingABoneAgainAndAgainStopsAtTheShortestBone) {
    // split_bone of one bone was accepted 29 times, down to 8.4e-9 long.
    Part part = testsupport::sharedSketchPart("tube");
    const double minimum = minimumBoneLength(part.mesh);
    BoneId bone = part.skeleton.bones().front().id;
    for (const Bone& b : part.skeleton.bones())
        if (part.skeleton.boneLength(b.id) > part.skeleton.boneLength(bone))
            bone = b.id;
    int splits = 0;
    for (; splits < 40; ++splits) {
        const Bone& b = part.skeleton.bone(bone);
        const Vec3 middle =
            0.5 * (part.skeleton.joint(b.head).position + part.skeleton.joint(b.tail).position);
        try {
            part = splitBoneAt(part, bone, middle).part;
        } catch (const Error& error) {
            EXPECT_TRUE(error.message().id == MessageId::SplitBoneTooShort ||
                        error.message().id == MessageId::SplitBoneLeadsNothing)
                << error.what();
            break;
        }
        expectNoShortBone(part, minimum, "after split " + std::to_string(splits + 1));
    }
    EXPECT_LT(splits, 12) << "halving cannot go on for long above the shortest bone";
    EXPECT_GE(splits, 1);
}

TEST(ShortBones, ADeleteThatWouldLeaveANeighbourTooShortIsRefused) {
    // Bones A-B and B-C, with joint A moved right beside the middle of B-C:
    // deleting B-C collapses it there, and A-(middle) would be tiny.
    const Part& part = testsupport::sharedSketchPart("star");
    ASSERT_GE(part.skeleton.boneCount(), 2) << "the star has an arm per bone";
    const Skeleton& skeleton = part.skeleton;
    // A bone B-C with another bone A-B at B.
    for (const Bone& middleBone : skeleton.bones()) {
        for (BoneId other : skeleton.bonesAt(middleBone.head)) {
            if (other == middleBone.id)
                continue;
            const Bone& ab = skeleton.bone(other);
            const JointId a = ab.head == middleBone.head ? ab.tail : ab.head;
            const Vec3 middle = 0.5 * (skeleton.joint(middleBone.head).position +
                                       skeleton.joint(middleBone.tail).position);
            Part moved = part;
            moved.skeleton.setJointPosition(a, middle + Vec3(0.0, 0.0, 1e-6));
            const Error error = errorOf([&] { deleteBone(moved, middleBone.id); });
            EXPECT_EQ(error.message().id, MessageId::DeleteLeavesShortBone) << error.what();
            return;
        }
    }
    FAIL() << "no bone with a neighbour at its head";
}

TEST(ShortBones, CollapsingMergesShortBonesIntoTheirNeighbours) {
    // Two junctions 0.01 apart (centre: up and down; second: right and a
    // leg), and a 0.005 twig at the end of the right arm.
    Skeleton skeleton;
    const JointId centre = skeleton.addJoint(Vec3(0, 0, 0));
    const JointId second = skeleton.addJoint(Vec3(0.01, 0, 0));
    const JointId up = skeleton.addJoint(Vec3(0, 1, 0));
    const JointId down = skeleton.addJoint(Vec3(0, -1, 0));
    const JointId right = skeleton.addJoint(Vec3(1, 0.2, 0));
    const JointId leg = skeleton.addJoint(Vec3(0.5, -1, 0));
    const JointId twig = skeleton.addJoint(Vec3(1.005, 0.2, 0));
    skeleton.addBone(centre, second);
    skeleton.addBone(centre, up);
    skeleton.addBone(centre, down);
    skeleton.addBone(second, right);
    skeleton.addBone(second, leg);
    skeleton.addBone(right, twig);
    EXPECT_EQ(collapseShortBones(skeleton, 0.1), 2);
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_FALSE(skeleton.hasJoint(twig)) << "the twig gave up its leaf end";
    EXPECT_EQ(skeleton.degree(centre), 4) << "the two junctions are one";
    EXPECT_EQ(skeleton.joint(right).position, Vec3(1, 0.2, 0)) << "the arm reaches as before";
    for (const Bone& bone : skeleton.bones())
        EXPECT_GE(skeleton.boneLength(bone.id), 0.1);
    EXPECT_TRUE(skeleton.isOrientedFromRoot());

    Skeleton one;
    one.addBone(one.addJoint(Vec3(0, 0, 0)), one.addJoint(Vec3(0.01, 0, 0)));
    EXPECT_EQ(collapseShortBones(one, 0.1), 0) << "a lone bone is the caller's to refuse";
}

// The auto-rig roots its skeleton at the thickest junction (the chest); a
// long prop in one hand (the dwarf's axe) puts the skeleton's middle, by
// bone length, at that hand. Collapsing a short bone leaves the root where
// it was.
TEST(ShortBones, CollapsingKeepsTheRootTheCallerChose) {
    Skeleton skeleton;
    const JointId chest = skeleton.addJoint(Vec3(0, 0, 0));
    const JointId head = skeleton.addJoint(Vec3(0, 1, 0));
    const JointId hand = skeleton.addJoint(Vec3(-2, 0, 0));
    skeleton.addBone(chest, head);
    skeleton.addBone(chest, skeleton.addJoint(Vec3(2, 0, 0)));
    skeleton.addBone(chest, hand);
    // The axe: a long handle and blade beyond the hand, a short stub below.
    skeleton.addBone(hand, skeleton.addJoint(Vec3(-2, 10, 0)));
    skeleton.addBone(hand, skeleton.addJoint(Vec3(-2, -0.5, 0)));
    // A twig at the head, shorter than the minimum.
    skeleton.addBone(head, skeleton.addJoint(Vec3(0, 1.01, 0)));
    skeleton.setRoot(chest);
    skeleton.reorient();
    ASSERT_EQ(chooseCentralRoot(skeleton), hand) << "the graph's middle is the hand";
    EXPECT_EQ(collapseShortBones(skeleton, 0.1), 1);
    EXPECT_EQ(skeleton.root(), chest);
    EXPECT_TRUE(skeleton.isOrientedFromRoot());
}

// A root that a collapse leaves as a leaf (its only other bone was short)
// gives way to the skeleton's most central joint.
TEST(ShortBones, ARootLeftALeafGivesWayToTheCentralJoint) {
    Skeleton skeleton;
    const JointId root = skeleton.addJoint(Vec3(0, 0, 0));
    const JointId middle = skeleton.addJoint(Vec3(1, 0, 0));
    const JointId stub = skeleton.addJoint(Vec3(0, 0.01, 0));
    skeleton.addBone(root, middle);
    skeleton.addBone(root, stub);
    skeleton.addBone(middle, skeleton.addJoint(Vec3(2, 0, 0)));
    skeleton.addBone(middle, skeleton.addJoint(Vec3(1, 1, 0)));
    skeleton.setRoot(root);
    skeleton.reorient();
    EXPECT_EQ(collapseShortBones(skeleton, 0.1), 1);
    EXPECT_NE(skeleton.degree(skeleton.root()), 1);
    EXPECT_EQ(skeleton.root(), middle);
    EXPECT_TRUE(skeleton.isOrientedFromRoot());
}

}  // namespace
}  // namespace rigmesh
