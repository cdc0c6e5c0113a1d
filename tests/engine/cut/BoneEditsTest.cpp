// Skeleton refinement (paper 3.3): splitting a bone adds exactly one joint
// and one bone, deleting one removes one of each; the skeleton stays a tree,
// the weights valid, the surface untouched, and only the re-skinned vertices
// change their weights.
#include <gtest/gtest.h>

#include "SharedSketchPart.h"
#include "base/Error.h"
#include "cut/BoneEdits.h"
#include "part/BoneWeights.h"

namespace rigmesh {
namespace {

BoneId longestBone(const Part& part) {
    BoneId best = part.skeleton.bones().front().id;
    for (const Bone& bone : part.skeleton.bones())
        if (part.skeleton.boneLength(bone.id) > part.skeleton.boneLength(best))
            best = bone.id;
    return best;
}

BoneId shortestBone(const Part& part) {
    BoneId best = part.skeleton.bones().front().id;
    for (const Bone& bone : part.skeleton.bones())
        if (part.skeleton.boneLength(bone.id) < part.skeleton.boneLength(best))
            best = bone.id;
    return best;
}

// The surface is untouched and every vertex outside the re-skin keeps its
// weights bit for bit (by bone id).
void expectLocal(const Part& before, const BoneEditResult& after) {
    EXPECT_TRUE(after.part.validateSolid().empty());
    EXPECT_EQ(after.part.mesh.vertices, before.mesh.vertices);
    EXPECT_EQ(after.part.mesh.faces, before.mesh.faces);
    const WeightsById& old = before.weights.perVertex;
    const WeightsById& now = after.part.weights.perVertex;
    std::vector<char> reskinned(before.mesh.vertexCount(), 0);
    for (int v : after.reskinned)
        reskinned[v] = 1;
    int changedOutside = 0;
    for (int v = 0; v < before.mesh.vertexCount(); ++v)
        if (!reskinned[v] && old[v] != now[v])
            ++changedOutside;
    // Only vertices that also had weight on a deleted bone may change there.
    EXPECT_LE(changedOutside, before.mesh.vertexCount() / 20);
}

class BoneEdits : public testing::TestWithParam<std::string> {};

TEST_P(BoneEdits, SplittingTheLongestBoneAddsOneJointAndReskinsLocally) {
    const Part& part = testsupport::sharedSketchPart(GetParam());
    const BoneId bone = longestBone(part);
    const Bone& b = part.skeleton.bone(bone);
    const Vec3 middle =
        0.5 * (part.skeleton.joint(b.head).position + part.skeleton.joint(b.tail).position);
    const BoneEditResult result = splitBoneAt(part, bone, middle);
    EXPECT_EQ(result.part.skeleton.boneCount(), part.skeleton.boneCount() + 1);
    EXPECT_EQ(result.part.skeleton.jointCount(), part.skeleton.jointCount() + 1);
    EXPECT_TRUE(result.part.skeleton.validate().empty());
    EXPECT_TRUE(result.part.skeleton.hasJoint(result.newJoint));
    expectLocal(part, result);
    // The far half took over the vertices beyond the new joint.
    EXPECT_FALSE(result.reskinned.empty());
    std::map<BoneId, int> leads = leadingVertexCounts(result.part.weights.perVertex);
    const Bone& half = result.part.skeleton.bone(bone);
    for (BoneId id : result.part.skeleton.bonesAt(result.newJoint))
        EXPECT_GT(leads[id], 0) << "bone " << id << " (split from " << bone << ", head "
                                << half.head << ")";
}

TEST_P(BoneEdits, DeletingTheShortestBoneRemovesOneJointOrIsRefusedForTheOnlyBone) {
    const Part& part = testsupport::sharedSketchPart(GetParam());
    if (part.skeleton.boneCount() < 2) {
        // A part keeps at least one bone: the delete is refused.
        EXPECT_THROW(deleteBone(part, shortestBone(part)), Error);
        return;
    }
    const BoneEditResult result = deleteBone(part, shortestBone(part));
    EXPECT_EQ(result.part.skeleton.boneCount(), part.skeleton.boneCount() - 1);
    EXPECT_EQ(result.part.skeleton.jointCount(), part.skeleton.jointCount() - 1);
    EXPECT_TRUE(result.part.skeleton.validate().empty());
    expectLocal(part, result);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, BoneEdits,
                         testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

TEST(BoneEditRefusals, SplitNearAJointAndDeletingTheOnlyBoneAreRefused) {
    const Part& tube = testsupport::sharedSketchPart("tube");
    const Bone& b = tube.skeleton.bones().front();
    EXPECT_THROW(splitBoneAt(tube, b.id, tube.skeleton.joint(b.head).position), Error);
    EXPECT_THROW(splitBoneAt(tube, 999, Vec3::Zero()), Error);
    Part single = tube;
    while (single.skeleton.boneCount() > 1)
        single = deleteBone(single, single.skeleton.bones().back().id).part;
    EXPECT_THROW(deleteBone(single, single.skeleton.bones().front().id), Error);
}

}  // namespace
}  // namespace rigmesh
