// A merge checks what it is given (paper 3.2 needs two closed, oriented
// surfaces that do not cross themselves) and makes no bone shorter than the
// shortest bone (rig/ShortBones.h): a split point beside a joint snaps to
// it, and joints to connect closer than that are refused.
#include <gtest/gtest.h>

#include "MergeTestSupport.h"
#include "base/Error.h"
#include "merge/SkeletonJoin.h"
#include "mesh/MeshSelfIntersections.h"

namespace rigmesh {
namespace {

using mergetest::sharedSketchPart;

Error mergeError(const Part& target, const Part& dragged) {
    MergeRequest request;
    request.join.draggedJoint = dragged.skeleton.root();
    request.join.targetJoint = target.skeleton.root();
    try {
        mergeParts(target, dragged, request);
    } catch (const Error& error) {
        return error;
    }
    ADD_FAILURE() << "the merge was accepted";
    return Error(std::string("none"));
}

TEST(MergeInputs, AnOpenTargetIsRefusedByName) {
    Part target = sharedSketchPart("tube");
    target.mesh.faces.pop_back();  // three border edges
    const Part& dragged = sharedSketchPart("y_branch");
    const Error error = mergeError(target, dragged);
    EXPECT_EQ(error.message().id, MessageId::MergeTargetNotSolid) << error.what();
    EXPECT_NE(std::string(error.what()).find("boundary edges"), std::string::npos) << error.what();
    // The part's own problem keeps its id inside the refusal, so the studio
    // translates both (Part::validateSolid).
    const std::vector<Message> expected = {{MessageId::PartSurfaceBoundaryEdges, {"3"}}};
    EXPECT_EQ(error.message().nested, expected) << error.what();
}

TEST(MergeInputs, ASelfIntersectingDraggedPartIsRefusedWhereverTheCrossingIs) {
    // One vertex pulled through the far side of the tube: faces cross far
    // from where the parts meet, which CGAL's corefinement does not notice.
    Part dragged = sharedSketchPart("tube");
    Vec3 centre = Vec3::Zero();
    for (const Vec3& v : dragged.mesh.vertices)
        centre += v;
    centre /= dragged.mesh.vertexCount();
    int farthest = 0;
    for (int v = 0; v < dragged.mesh.vertexCount(); ++v)
        if ((dragged.mesh.vertices[v] - centre).norm() >
            (dragged.mesh.vertices[farthest] - centre).norm())
            farthest = v;
    const Vec3 from = dragged.mesh.vertices[farthest];
    dragged.mesh.vertices[farthest] = centre + 1.5 * (centre - from);
    ASSERT_GT(countSelfIntersectingFacePairs(dragged.mesh), 0);
    ASSERT_TRUE(dragged.validateSolid().empty()) << "still closed and oriented";
    const Part& target = sharedSketchPart("y_branch");
    const Error error = mergeError(target, dragged);
    EXPECT_EQ(error.message().id, MessageId::MergeDraggedIntersectsItself) << error.what();
}

Skeleton oneBone(double length) {
    // Joint 0 at the origin, joint 1 at `length` (added one after the other:
    // the order of a call's arguments is unspecified).
    Skeleton skeleton;
    const JointId head = skeleton.addJoint(Vec3(0, 0, 0));
    skeleton.addBone(head, skeleton.addJoint(Vec3(length, 0, 0)));
    return skeleton;
}

TEST(MergeInputs, ASplitBesideAJointSnapsToTheJoint) {
    const Skeleton target = oneBone(1.0);
    const Skeleton dragged = oneBone(0.5);
    SkeletonJoinRequest request;
    request.mode = MergeMode::Split;
    request.draggedJoint = 0;
    request.targetBone = 0;
    // 8% along: past the 5% snap, within the shortest bone of 0.1.
    request.splitPoint = Vec3(0.08, 0.0, 0.0);
    const SkeletonJoin near = joinSkeletons(target, dragged, request, 0.1);
    EXPECT_EQ(near.meetingJoint, 0u);
    EXPECT_FALSE(near.splitTail);
    request.splitPoint = Vec3(0.93, 0.0, 0.0);
    EXPECT_EQ(joinSkeletons(target, dragged, request, 0.1).meetingJoint, 1u);
    // Farther in, the bone is split and both halves are long enough.
    request.splitPoint = Vec3(0.15, 0.0, 0.0);
    const SkeletonJoin split = joinSkeletons(target, dragged, request, 0.1);
    ASSERT_TRUE(split.splitTail);
    for (const Bone& bone : split.skeleton.bones())
        EXPECT_GE(split.skeleton.boneLength(bone.id), 0.1);
}

TEST(MergeInputs, JointsToConnectCloserThanTheShortestBoneAreRefused) {
    const Skeleton target = oneBone(1.0);
    Skeleton dragged;
    const JointId near = dragged.addJoint(Vec3(1.05, 0, 0));  // joint 0
    dragged.addBone(near, dragged.addJoint(Vec3(2, 0, 0)));
    SkeletonJoinRequest request;
    request.mode = MergeMode::Connect;
    request.draggedJoint = 0;
    request.targetJoint = 1;
    try {
        joinSkeletons(target, dragged, request, 0.1);
        ADD_FAILURE() << "a 0.05 bone was made";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::MergeJointsTooClose) << error.what();
    }
    EXPECT_NO_THROW(joinSkeletons(target, dragged, request, 0.01));
}

}  // namespace
}  // namespace rigmesh
