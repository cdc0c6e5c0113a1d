// The pose commands: SetPoseCommand (apply, undo, merging of drags, live
// previews), ResetPoseCommand, SetJointPinnedCommand, bad ids, and the pose
// and pins across RebuildPartCommand.
#include <QSignalSpy>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "base/Error.h"
#include "model/RigCarryOver.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/preview/PosePreview.h"

namespace rigmesh::model::test {
namespace {

struct Posed {
    Document document;
    PartId id = kNoPart;
    std::vector<JointId> ends;

    Posed() {
        // Root with three subtrees, two of them chains: pins leave IK room.
        id = addPart(document, sharedStroke("biped"), QStringLiteral("Y"));
        document.undoStack()->clear();
        ends = endJoints(node().part->skeleton);
    }
    const PartNode& node() const { return document.part(id); }
    QUndoStack& stack() { return *document.undoStack(); }
    void drag(JointId joint, const Vec3& offset) {
        stack().push(new SetPoseCommand(document, id, dragged(node(), joint, offset), joint));
    }
};

bool hasChange(const QSignalSpy& spy, Document::Change change) {
    for (const QList<QVariant>& args : spy) {
        if (args.at(1).value<Document::Changes>() & change)
            return true;
    }
    return false;
}

TEST(PoseCommands, NewPartsStartInTheirRestPose) {
    Posed p;
    ASSERT_GE(p.ends.size(), 2u);
    EXPECT_TRUE(identicalPoses(p.node().pose, restPose(p.node().part->skeleton)));
    EXPECT_TRUE(p.node().pinnedJoints.empty());
}

TEST(PoseCommands, SetPoseAppliesAndUndoes) {
    Posed p;
    const rigmesh::Pose rest = p.node().pose;
    const JointId joint = p.ends[0];
    const rigmesh::Pose to = dragged(p.node(), joint, Vec3(0.1, 0.15, 0.05));
    ASSERT_FALSE(identicalPoses(to, rest));
    QSignalSpy changed(&p.document, &Document::partChanged);
    p.stack().push(new SetPoseCommand(p.document, p.id, to, joint));
    EXPECT_TRUE(identicalPoses(p.node().pose, to));
    EXPECT_TRUE(hasChange(changed, Document::Change::Pose));
    EXPECT_EQ(p.stack().count(), 1);
    EXPECT_EQ(p.stack().text(0), QStringLiteral("Pose Joint %1").arg(joint));
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
    p.stack().redo();
    EXPECT_TRUE(identicalPoses(p.node().pose, to));

    // Without a dragged joint the text names the part.
    p.stack().push(new SetPoseCommand(p.document, p.id, rest));
    EXPECT_EQ(p.stack().text(1), QStringLiteral("Pose Y"));
}

TEST(PoseCommands, DragsOfOneJointMergeOfTwoJointsDoNot) {
    Posed p;
    const rigmesh::Pose rest = p.node().pose;
    for (int step = 1; step <= 5; ++step)
        p.drag(p.ends[0], Vec3(0.03 * step, 0.02 * step, 0.0));
    EXPECT_EQ(p.stack().count(), 1);
    const rigmesh::Pose afterFirst = p.node().pose;
    for (int step = 1; step <= 4; ++step)
        p.drag(p.ends[1], Vec3(0.0, -0.03 * step, 0.02 * step));
    EXPECT_EQ(p.stack().count(), 2);
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, afterFirst));
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
}

TEST(PoseCommands, DragBackToTheStartDropsTheStep) {
    Posed p;
    p.drag(p.ends[0], Vec3(0.1, 0.1, 0.0));
    const rigmesh::Pose posed = p.node().pose;
    p.drag(p.ends[1], Vec3(0.0, 0.1, 0.1));
    ASSERT_EQ(p.stack().count(), 2);
    p.stack().push(new SetPoseCommand(p.document, p.id, posed, p.ends[1]));
    EXPECT_EQ(p.stack().count(), 1);
    EXPECT_TRUE(identicalPoses(p.node().pose, posed));
    // A pose change that changes nothing is not pushed at all.
    p.stack().push(new SetPoseCommand(p.document, p.id, posed, p.ends[2]));
    EXPECT_EQ(p.stack().count(), 1);
}

TEST(PoseCommands, LivePreviewIsOneStepFromThePoseBeforeIt) {
    Posed p;
    const rigmesh::Pose rest = p.node().pose;
    const JointId joint = p.ends[0];
    QSignalSpy changed(&p.document, &Document::partChanged);
    PosePreview preview(p.document, p.id);
    for (int step = 1; step <= 3; ++step)
        preview.preview(dragged(p.node(), joint, Vec3(0.04 * step, 0.0, 0.03)));
    EXPECT_EQ(changed.count(), 3);
    ASSERT_TRUE(preview.previewing());
    EXPECT_TRUE(identicalPoses(preview.original(), rest));
    const rigmesh::Pose last = p.node().pose;
    EXPECT_TRUE(preview.commit(joint));
    EXPECT_EQ(p.stack().count(), 1);
    EXPECT_FALSE(preview.previewing());
    EXPECT_TRUE(identicalPoses(p.node().pose, last));
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
    p.stack().redo();
    EXPECT_TRUE(identicalPoses(p.node().pose, last));

    // A cancelled preview puts the pose back and leaves no step.
    PosePreview cancelled(p.document, p.id);
    cancelled.preview(dragged(p.node(), p.ends[1], Vec3(0.1, 0.0, 0.0)));
    cancelled.revert();
    EXPECT_TRUE(identicalPoses(p.node().pose, last));
    EXPECT_EQ(p.stack().count(), 1);
}

TEST(PoseCommands, ResetRestoresRestAndUndoRestoresThePoseExactly) {
    Posed p;
    const rigmesh::Pose rest = p.node().pose;
    p.drag(p.ends[0], Vec3(0.1, -0.05, 0.1));
    p.drag(p.ends[1], Vec3(-0.08, 0.1, 0.0));
    const rigmesh::Pose posed = p.node().pose;
    p.stack().push(new ResetPoseCommand(p.document, p.id));
    EXPECT_EQ(p.stack().text(p.stack().count() - 1), QStringLiteral("Reset pose of Y"));
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, posed));
    p.stack().redo();
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
    // Already at rest: nothing to push.
    const int count = p.stack().count();
    p.stack().push(new ResetPoseCommand(p.document, p.id));
    EXPECT_EQ(p.stack().count(), count);
}

TEST(PoseCommands, PinAndUnpin) {
    Posed p;
    const JointId joint = p.ends[2];
    QSignalSpy changed(&p.document, &Document::partChanged);
    p.stack().push(new SetJointPinnedCommand(p.document, p.id, joint, true));
    EXPECT_EQ(p.node().pinnedJoints, std::set<JointId>{joint});
    EXPECT_EQ(p.stack().text(0), QStringLiteral("Pin Joint %1").arg(joint));
    EXPECT_TRUE(hasChange(changed, Document::Change::Pins));

    // IK keeps the pinned end in place while another end is dragged.
    p.drag(p.ends[1], Vec3(0.1, 0.1, 0.0));
    EXPECT_FALSE(identicalPoses(p.node().pose, restPose(p.node().part->skeleton)));
    EXPECT_TRUE(p.node().pose.rotation(joint).isApprox(Eigen::Quaterniond::Identity()));

    p.stack().push(new SetJointPinnedCommand(p.document, p.id, joint, false));
    EXPECT_TRUE(p.node().pinnedJoints.empty());
    EXPECT_EQ(p.stack().text(2), QStringLiteral("Unpin Joint %1").arg(joint));
    p.stack().undo();
    EXPECT_EQ(p.node().pinnedJoints, std::set<JointId>{joint});
    p.stack().undo();
    p.stack().undo();
    EXPECT_TRUE(p.node().pinnedJoints.empty());
    // Pinning a joint twice pushes nothing the second time.
    p.stack().push(new SetJointPinnedCommand(p.document, p.id, joint, true));
    p.stack().push(new SetJointPinnedCommand(p.document, p.id, joint, true));
    EXPECT_EQ(p.stack().count(), 1);
}

TEST(PoseCommands, UnknownPartsAndJointsThrowAndPushNothing) {
    Posed p;
    const PartId missing = 999;
    const JointId badJoint = 424242;
    const rigmesh::Pose rest = p.node().pose;
    EXPECT_THROW(SetPoseCommand(p.document, missing, rest), rigmesh::Error);
    EXPECT_THROW(SetPoseCommand(p.document, p.id, rest, badJoint), rigmesh::Error);
    rigmesh::Pose foreign = rest;
    foreign.setRotation(badJoint, Eigen::Quaterniond::Identity());
    EXPECT_THROW(SetPoseCommand(p.document, p.id, foreign), rigmesh::Error);
    rigmesh::Pose zero = rest;
    zero.setRotation(p.ends[0], Eigen::Quaterniond(0, 0, 0, 0));
    EXPECT_THROW(SetPoseCommand(p.document, p.id, zero), rigmesh::Error);
    EXPECT_THROW(ResetPoseCommand(p.document, missing), rigmesh::Error);
    EXPECT_THROW(SetJointPinnedCommand(p.document, missing, p.ends[0], true), rigmesh::Error);
    EXPECT_THROW(SetJointPinnedCommand(p.document, p.id, badJoint, true), rigmesh::Error);
    EXPECT_THROW(p.document.setPose(p.id, foreign), rigmesh::Error);
    EXPECT_THROW(p.document.setPinnedJoints(p.id, {badJoint}), rigmesh::Error);
    EXPECT_EQ(p.stack().count(), 0);
    EXPECT_TRUE(identicalPoses(p.node().pose, rest));
    EXPECT_TRUE(p.node().pinnedJoints.empty());
}

TEST(PoseCommands, RebuildKeepsThePoseAndPinsOfKeptJointsAndUndoRestoresThem) {
    Posed p;
    p.stack().push(new SetJointPinnedCommand(p.document, p.id, p.ends[2], true));
    p.drag(p.ends[0], Vec3(0.1, 0.1, 0.05));
    ASSERT_FALSE(identicalPoses(p.node().pose, restPose(p.node().part->skeleton)));
    const rigmesh::Pose posed = p.node().pose;
    const std::set<JointId> pins = p.node().pinnedJoints;
    const QByteArray before = bytesOf(p.document);

    BuildOptions options;
    options.smoothing = false;  // the same skeleton: everything is kept
    auto command = RebuildPartCommand::create(p.document, p.id, options);
    EXPECT_TRUE(command->droppedMessage().isEmpty()) << command->droppedMessage().toStdString();
    p.stack().push(command.release());
    EXPECT_TRUE(identicalPoses(p.node().pose, posed));
    EXPECT_EQ(p.node().pinnedJoints, pins);

    // Another edge length: whatever the new skeleton keeps keeps its values.
    options.targetEdgeLength = 0.15;
    command = RebuildPartCommand::create(p.document, p.id, options);
    const bool dropsSome = !command->droppedMessage().isEmpty();
    p.stack().push(command.release());
    const Skeleton& skeleton = p.node().part->skeleton;
    for (const auto& [joint, rotation] : p.node().pose.rotations) {
        ASSERT_TRUE(skeleton.hasJoint(joint));
        EXPECT_EQ(rotation.coeffs(), posed.rotation(joint).coeffs());
    }
    for (JointId joint : p.node().pinnedJoints)
        EXPECT_TRUE(pins.contains(joint) && skeleton.hasJoint(joint));
    if (!dropsSome) {
        EXPECT_TRUE(identicalPoses(p.node().pose, posed));
        EXPECT_EQ(p.node().pinnedJoints, pins);
    }

    p.stack().undo();
    p.stack().undo();
    EXPECT_TRUE(identicalPoses(p.node().pose, posed));
    EXPECT_EQ(p.node().pinnedJoints, pins);
    EXPECT_EQ(bytesOf(p.document), before);
}

TEST(RigCarryOver, JointsThatMovedOrVanishedAreDroppedAndCounted) {
    Skeleton from;
    const JointId a = from.addJoint(Vec3(0, 0, 0));
    const JointId b = from.addJoint(Vec3(1, 0, 0));
    const JointId c = from.addJoint(Vec3(2, 0, 0));
    from.addBone(a, b);
    from.addBone(b, c);
    from.setRoot(a);
    Skeleton to = from;
    to.setJointPosition(c, Vec3(2, 1, 0));  // a whole bone away: not the same joint
    rigmesh::Pose pose;
    pose.setRotation(a, Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Vec3::UnitZ())));
    pose.setRotation(c, Eigen::Quaterniond(Eigen::AngleAxisd(0.2, Vec3::UnitZ())));
    pose.rootTranslation = Vec3(0.5, 0, 0);
    rigmesh::Clip clip(30.0);
    clip.setKey(1.0, pose);
    const CarriedRig carried = carryRigOver(from, to, pose, {b, c}, clip);
    EXPECT_EQ(carried.pose.rotations.size(), 1u);
    EXPECT_TRUE(carried.pose.rotations.contains(a));
    EXPECT_EQ(carried.pose.rootTranslation, pose.rootTranslation);
    EXPECT_EQ(carried.pinned, std::set<JointId>{b});
    ASSERT_EQ(carried.clip.keyCount(), 1);
    EXPECT_EQ(carried.clip.framesPerSecond(), 30.0);
    EXPECT_FALSE(carried.clip.key(1.0).rotations.contains(c));
    EXPECT_EQ(carried.keptJoints, 2);     // a (posed), b (pinned)
    EXPECT_EQ(carried.droppedJoints, 1);  // c (posed, pinned, keyed)
}

}  // namespace
}  // namespace rigmesh::model::test
