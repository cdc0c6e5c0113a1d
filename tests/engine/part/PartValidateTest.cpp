// Part::validate() on skin weights keyed by bone id: a
// weight, failed bone or known closest bone naming a bone the skeleton does
// not have is reported, and so are weights out of bone id order.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "ProblemMentions.h"
#include "SharedSketchPart.h"
#include "cut/BoneEdits.h"

namespace rigmesh {
namespace {

using testsupport::mentions;

// A weighted leaf bone of the y_branch and a vertex it weights.
struct LeafWeight {
    BoneId bone;
    int vertex;
};

LeafWeight leafWeight(const Part& part) {
    for (const Bone& bone : part.skeleton.bones())
        if (part.skeleton.degree(bone.tail) == 1)
            for (int v = 0; v < part.mesh.vertexCount(); ++v)
                for (const auto& entry : part.weights.perVertex[v])
                    if (entry.first == bone.id)
                        return {bone.id, v};
    ADD_FAILURE() << "no weighted leaf bone";
    return {0, 0};
}

TEST(PartValidate, AFreshPartIsValid) {
    const Part& part = testsupport::sharedSketchPart("y_branch");
    EXPECT_TRUE(part.validate().empty()) << part.validate().front();
}

TEST(PartValidate, AWeightNamingABoneTheSkeletonDoesNotHaveIsReported) {
    Part part = testsupport::sharedSketchPart("y_branch");
    const LeafWeight leaf = leafWeight(part);
    // The bone goes but its weights stay: the other bones' weights are
    // untouched (they are keyed by id), and the stale ones are caught.
    part.skeleton.removeJoint(part.skeleton.bone(leaf.bone).tail);
    const std::vector<Message> problems = part.validate();
    EXPECT_TRUE(mentions(problems, "The skin weights of vertex " + std::to_string(leaf.vertex) +
                                       " name bone " + std::to_string(leaf.bone) +
                                       ", which the skeleton does not have."))
        << englishText(problems);
}

TEST(PartValidate, AFailedOrKnownClosestBoneTheSkeletonDoesNotHaveIsReported) {
    Part part = testsupport::sharedSketchPart("y_branch");
    const BoneId missing = 1000;
    part.weights.failedBones = {missing};
    EXPECT_TRUE(mentions(part.validate(), "The failed bones name a missing bone."));
    part.weights.failedBones.clear();
    ASSERT_FALSE(part.knownClosestBones.empty());
    part.knownClosestBones[0] = {{missing, 0.1}};
    EXPECT_TRUE(mentions(part.validate(), "The known closest bones of vertex 0 name bone 1000"));
}

TEST(PartValidate, WeightsOutOfBoneIdOrderAreReported) {
    Part part = testsupport::sharedSketchPart("y_branch");
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if (part.weights.perVertex[v].size() > 1) {
            std::reverse(part.weights.perVertex[v].begin(), part.weights.perVertex[v].end());
            EXPECT_TRUE(mentions(
                part.validate(),
                "The skin weights of vertex " + std::to_string(v) + " are not in bone order."));
            return;
        }
    FAIL() << "no vertex with two bones";
}

// Deleting a bone shifts the bones after it in the bone list but changes no
// bone id: every vertex the re-skin left alone, and that the bone did not
// weight, keeps its bones and their weights (renormalised: to rounding).
TEST(PartValidate, DeletingABoneKeepsTheOtherBonesWeightsByIdAndTheResultValid) {
    const Part& part = testsupport::sharedSketchPart("biped");
    const LeafWeight leaf = leafWeight(part);
    const int position = part.skeleton.indexOfBone(leaf.bone);
    ASSERT_LT(position + 1, part.skeleton.boneCount()) << "a bone after it shifts";
    const BoneEditResult edited = deleteBone(part, leaf.bone);
    EXPECT_TRUE(edited.part.validate().empty()) << edited.part.validate().front();
    EXPECT_EQ(edited.part.skeleton.indexOfBone(part.skeleton.bones()[position + 1].id), position);
    std::vector<char> reskinned(part.mesh.vertexCount(), 0);
    for (int v : edited.reskinned)
        reskinned[v] = 1;
    int kept = 0;
    for (int v = 0; v < part.mesh.vertexCount(); ++v)
        if (!reskinned[v] &&
            std::none_of(part.weights.perVertex[v].begin(), part.weights.perVertex[v].end(),
                         [&](const auto& entry) { return entry.first == leaf.bone; })) {
            const auto& now = edited.part.weights.perVertex[v];
            const auto& was = part.weights.perVertex[v];
            ASSERT_EQ(now.size(), was.size()) << v;
            for (std::size_t i = 0; i < now.size(); ++i) {
                EXPECT_EQ(now[i].first, was[i].first) << v;
                EXPECT_NEAR(now[i].second, was[i].second, 1e-12) << v;
            }
            ++kept;
        }
    EXPECT_GT(kept, 0) << "the delete re-skinned every vertex";
}

}  // namespace
}  // namespace rigmesh
