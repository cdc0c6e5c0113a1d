// Merging two rigged parts (paper 3.2): every mode on pairs of shared
// sketches at several angles gives one valid rigged part whose untouched
// vertices kept their positions, and bad merges are refused.
#include <cmath>
#include <tuple>

#include "MergeTestSupport.h"
#include "base/Error.h"

namespace rigmesh::mergetest {
namespace {

struct MergeCase {
    std::string target, dragged;
    MergeMode mode;
    double angleDegrees;
};

std::string modeName(MergeMode mode) {
    return mode == MergeMode::Snap ? "snap" : mode == MergeMode::Split ? "split" : "connect";
}

// The dragged sketch turned by the angle about the view axis and placed so
// that its top-most joint sits a quarter of the way along the target's
// longest bone, a little off it (so connect makes a bone of some length).
struct PlacedMerge {
    Part dragged;
    MergeRequest request;
};

PlacedMerge place(const MergeCase& c) {
    const Part& target = sharedSketchPart(c.target);
    const Skeleton& ts = target.skeleton;
    BoneId longest = ts.bones().front().id;
    for (const Bone& bone : ts.bones())
        if (ts.boneLength(bone.id) > ts.boneLength(longest))
            longest = bone.id;
    const Bone& bone = ts.bone(longest);
    const Vec3 anchor = 0.75 * ts.joint(bone.head).position + 0.25 * ts.joint(bone.tail).position;

    Part dragged = rotated(sharedSketchPart(c.dragged), Vec3::UnitZ(), c.angleDegrees * M_PI / 180);
    const JointId top = extremeJoint(dragged, 1, true);
    const Vec3 offset = 0.1 * ts.boneLength(longest) * Vec3(0.3, -1.0, 0.2).normalized();
    dragged = translated(dragged, anchor + offset - dragged.skeleton.joint(top).position);

    MergeRequest request;
    request.join.mode = c.mode;
    request.join.draggedJoint = top;
    request.join.targetJoint = nearestJoint(target, anchor);
    request.join.targetBone = longest;
    request.join.splitPoint = anchor + offset;
    return {dragged, request};
}

class MergeModes : public testing::TestWithParam<MergeCase> {};

TEST_P(MergeModes, GivesOneValidRiggedPartAndKeepsUntouchedVertices) {
    const MergeCase& c = GetParam();
    const Part& target = sharedSketchPart(c.target);
    const PlacedMerge placed = place(c);
    const MergeResult result = mergeParts(target, placed.dragged, placed.request);
    expectValidMergedPart(result.part, result.requestedBones);

    // One tree holding every bone of both (the connect bone or split half
    // added, pruned ones removed).
    const int added = c.mode == MergeMode::Snap ? 0 : 1;
    EXPECT_EQ(result.part.skeleton.boneCount() + result.stats.prunedBones,
              target.skeleton.boneCount() + placed.dragged.skeleton.boneCount() + added);
    EXPECT_TRUE(result.part.skeleton.validate().empty());
    EXPECT_TRUE(result.part.skeleton.isOrientedFromRoot());

    // Every unchanged vertex kept its position bit for bit, unless the seam
    // smoothing moved it (paper 3.2.1: only the band moves).
    std::vector<char> moved(result.part.mesh.vertexCount(), 0);
    for (int v : result.movedVertices)
        moved[v] = 1;
    int kept = 0;
    for (int v = 0; v < result.part.mesh.vertexCount(); ++v) {
        const VertexSource& s = result.sources[v];
        if (s.kind != VertexSource::Kind::Vertex || moved[v])
            continue;
        const Vec3 before = s.mesh == 0
                                ? target.mesh.vertices[s.index]
                                : placed.dragged.mesh.vertices[s.index] + result.draggedTranslation;
        ASSERT_EQ(result.part.mesh.vertices[v], before) << "vertex " << v;
        ++kept;
    }
    EXPECT_GT(kept, result.part.mesh.vertexCount() / 2);
    EXPECT_LT(result.stats.smoothedVertices, result.part.mesh.vertexCount() / 3);
    // Snap and connect are local: fewer vertices re-skinned than the part
    // has (a split re-skins everything weighted on the split bone, which is
    // half of a two-bone body).
    if (c.mode != MergeMode::Split) {
        EXPECT_LT(result.stats.verticesInvolved, result.part.mesh.vertexCount());
    }
}

std::vector<MergeCase> cases() {
    std::vector<MergeCase> list;
    const std::vector<std::pair<std::string, std::string>> pairs{
        {"camel_body", "camel_leg"}, {"biped", "banana"}, {"star", "tube"}};
    for (const auto& [target, dragged] : pairs)
        for (MergeMode mode : {MergeMode::Snap, MergeMode::Split, MergeMode::Connect})
            for (double angle : {0.0, 35.0, -70.0})
                list.push_back({target, dragged, mode, angle});
    return list;
}

INSTANTIATE_TEST_SUITE_P(SharedSketchPairs, MergeModes, testing::ValuesIn(cases()),
                         [](const testing::TestParamInfo<MergeCase>& param) {
                             const MergeCase& c = param.param;
                             return c.target + "_" + c.dragged + "_" + modeName(c.mode) + "_" +
                                    (c.angleDegrees < 0 ? "minus" : "") +
                                    std::to_string(static_cast<int>(std::abs(c.angleDegrees)));
                         });

// Merging `dragged` into the camel body (connect, first joints) throws an
// Error whose message contains `reason`.
void expectRefused(const Part& dragged, const std::string& reason) {
    const Part& body = sharedSketchPart("camel_body");
    MergeRequest request;
    request.join.mode = MergeMode::Connect;
    request.join.draggedJoint = dragged.skeleton.joints().front().id;
    request.join.targetJoint = body.skeleton.joints().front().id;
    try {
        mergeParts(body, dragged, request);
        ADD_FAILURE() << "merged although: " << reason;
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
}

TEST(MergeRefusals, PartsThatDoNotTouchAreRefusedWithAMessage) {
    expectRefused(translated(sharedSketchPart("camel_leg"), Vec3(40.0, 0.0, 0.0)), "do not touch");
}

TEST(MergeRefusals, APartInsideTheOtherIsRefusedWithAMessage) {
    Part small = sharedSketchPart("camel_head");
    for (Vec3& p : small.mesh.vertices)
        p *= 0.05;
    for (const Joint& joint : std::vector<Joint>(small.skeleton.joints()))
        small.skeleton.setJointPosition(joint.id, joint.position * 0.05);
    expectRefused(small, "inside");
}

TEST(MergeRefusals, UnknownJointsAreRefused) {
    const Part& body = sharedSketchPart("camel_body");
    const Part leg = translated(sharedSketchPart("camel_leg"), Vec3(1.7, -0.55, 0.3));
    MergeRequest request;
    request.join.mode = MergeMode::Snap;
    request.join.draggedJoint = 999;
    request.join.targetJoint = 0;
    EXPECT_THROW(mergeParts(body, leg, request), Error);
}

TEST(MergeReskin, LocalWeightsStayCloseToGlobalOnTheCamelLeg) {
    const Part& body = sharedSketchPart("camel_body");
    const Part leg = translated(sharedSketchPart("camel_leg"), Vec3(1.7, -0.55, 0.3));
    MergeRequest request;
    request.join.mode = MergeMode::Connect;
    request.join.draggedJoint = extremeJoint(leg, 1, true);
    request.join.targetJoint =
        nearestJoint(body, leg.skeleton.joint(request.join.draggedJoint).position);
    request.compareGlobal = true;
    const MergeResult result = mergeParts(body, leg, request);
    EXPECT_LE(result.stats.p90WeightDifference, 0.07);
    EXPECT_GT(result.stats.verticesInvolved, 0);
    EXPECT_LT(result.stats.verticesInvolved, result.stats.vertices / 2);
}

}  // namespace
}  // namespace rigmesh::mergetest
