// The paper's edits on skeletons with disconnected bones (part/BoneConnection.h):
// cut and merge refuse them and name the bone, Connect Bone joins a bone to
// its parent, split and delete carry the chains along.
#include <gtest/gtest.h>

#include <functional>

#include "PartTestSupport.h"
#include "base/Error.h"
#include "cut/BoneEdits.h"
#include "cut/CutPart.h"
#include "io/SceneImport.h"
#include "merge/MergeParts.h"
#include "part/BoneConnection.h"

namespace rigmesh::parttest {
namespace {

// The biped with the bones leaving one junction disconnected: their heads
// are a joint of their own at the junction, attached to the bone ending
// there (a chain hanging at its parent's tail, as a Blender file may have).
struct Disconnected {
    Part part;
    BoneId parent = kNoBone;
    JointId chain = kNoJoint;
};

Disconnected disconnectAJunction() {
    Disconnected out;
    out.part = sharedPart("biped").part;
    Skeleton& s = out.part.skeleton;
    for (const Joint& joint : s.joints()) {
        const std::vector<BoneId> children = s.childrenOf(joint.id);
        const std::optional<BoneId> ending = boneForJoint(s, joint.id);
        if (joint.id == s.root() || children.size() < 2 || !ending)
            continue;
        std::vector<Joint> joints = s.joints();
        std::vector<Bone> bones = s.bones();
        const JointId head =
            std::max_element(joints.begin(), joints.end(),
                             [](const Joint& a, const Joint& b) { return a.id < b.id; })
                ->id +
            1;
        joints.push_back({head, joint.position});
        for (Bone& bone : bones)
            if (bone.head == joint.id)
                bone.head = head;
        s = Skeleton::restore(joints, bones, s.root(), {{head, *ending}});
        out.parent = *ending;
        out.chain = head;
        return out;
    }
    ADD_FAILURE() << "the biped has no junction below its root";
    return out;
}

MessageId messageOf(const std::function<void()>& edit) {
    try {
        edit();
    } catch (const Error& error) {
        return error.message().id;
    }
    return MessageId::None;
}

TEST(BoneConnection, ADisconnectedPartIsValid) {
    const Disconnected d = disconnectAJunction();
    EXPECT_TRUE(d.part.validateSolid().empty()) << d.part.validateSolid().front();
    EXPECT_TRUE(firstDisconnectedBone(d.part.skeleton).has_value());
}

TEST(BoneConnection, CutAndMergeRefuseAndNameTheBone) {
    Disconnected d = disconnectAJunction();
    const BoneId named = *firstDisconnectedBone(d.part.skeleton);
    d.part.boneNames[named] = "thigh.L";
    try {
        cutPart(d.part, CutRequest{});
        ADD_FAILURE() << "the cut went ahead";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::BoneNotConnected);
        EXPECT_NE(std::string(error.what())
                      .find("Bone 'thigh.L' is not connected to its parent; "
                            "connect it first (Edit > Connect Bone)"),
                  std::string::npos)
            << error.what();
    }
    const Part& other = sharedPart("tube").part;
    EXPECT_EQ(messageOf([&] { mergeParts(other, d.part, MergeRequest{}); }),
              MessageId::BoneNotConnected);
    EXPECT_EQ(messageOf([&] { mergeParts(d.part, other, MergeRequest{}); }),
              MessageId::BoneNotConnected);
}

TEST(BoneConnection, ConnectBoneJoinsTheHeadToItsParentsTail) {
    const Disconnected d = disconnectAJunction();
    const BoneId bone = d.part.skeleton.childrenOf(d.chain).front();
    const Part connected = connectBone(d.part, bone);
    EXPECT_TRUE(connected.skeleton.isConnectedTree());
    EXPECT_TRUE(connected.validateSolid().empty());
    EXPECT_TRUE(connected.skeleton.isConnected(bone));
    EXPECT_EQ(connected.skeleton.bone(bone).head, d.part.skeleton.bone(d.parent).tail);
    EXPECT_EQ(connected.mesh.vertices, d.part.mesh.vertices);
    EXPECT_EQ(connected.weights.perVertex, d.part.weights.perVertex);
    // It is the biped's own skeleton again, but for the joint that went.
    const Skeleton& biped = sharedPart("biped").part.skeleton;
    EXPECT_EQ(connected.skeleton.boneCount(), biped.boneCount());
    for (const Bone& b : biped.bones())
        EXPECT_EQ(connected.skeleton.bone(b.id).head, b.head);

    EXPECT_EQ(messageOf([&] { connectBone(connected, bone); }),
              MessageId::ConnectBoneAlreadyConnected);
    const BoneId rootBone = connected.skeleton.childrenOf(connected.skeleton.root()).front();
    EXPECT_EQ(messageOf([&] { connectBone(connected, rootBone); }),
              MessageId::ConnectBoneHasNoParent);
}

TEST(BoneConnection, AFurtherRootChainConnectsToTheNearestJoint) {
    Disconnected d = disconnectAJunction();
    d.part.skeleton.attach(d.chain, kNoBone);
    ASSERT_TRUE(d.part.skeleton.validate().empty());
    const BoneId bone = d.part.skeleton.childrenOf(d.chain).front();
    const Part connected = connectBone(d.part, bone);
    EXPECT_TRUE(connected.skeleton.isConnectedTree());
    EXPECT_EQ(connected.skeleton.bone(bone).head, d.part.skeleton.bone(d.parent).tail)
        << "the junction's own joint is the nearest";
}

TEST(BoneConnection, SplitAndDeleteCarryTheChains) {
    const Disconnected d = disconnectAJunction();
    // Splitting the bone the chain hangs from: the chain, at its tail, stays
    // with the half nearer it, the tail half.
    const BoneEditResult split =
        splitBoneAt(d.part, d.parent,
                    0.5 * (d.part.skeleton.joint(d.part.skeleton.bone(d.parent).head).position +
                           d.part.skeleton.joint(d.part.skeleton.bone(d.parent).tail).position));
    EXPECT_TRUE(split.part.validateSolid().empty());
    const BoneId tailHalf = split.part.skeleton.attachments().at(d.chain);
    EXPECT_NE(tailHalf, d.parent);
    EXPECT_EQ(split.part.skeleton.bone(tailHalf).tail, d.part.skeleton.bone(d.parent).tail);

    // Deleting it: the chain hangs from the bone above.
    const std::optional<BoneId> above = d.part.skeleton.parentBone(d.parent);
    const BoneEditResult removed = deleteBone(d.part, d.parent);
    EXPECT_TRUE(removed.part.validateSolid().empty());
    EXPECT_EQ(removed.part.skeleton.attachments().at(d.chain), above.value_or(kNoBone));

    // Splitting a bone of the chain keeps it hanging where it was.
    const BoneId chainBone = d.part.skeleton.childrenOf(d.chain).front();
    const Bone& b = d.part.skeleton.bone(chainBone);
    const BoneEditResult inChain = splitBoneAt(
        d.part, chainBone,
        0.5 * (d.part.skeleton.joint(b.head).position + d.part.skeleton.joint(b.tail).position));
    EXPECT_TRUE(inChain.part.validateSolid().empty());
    EXPECT_EQ(inChain.part.skeleton.attachments().at(d.chain), d.parent);
}

}  // namespace
}  // namespace rigmesh::parttest
