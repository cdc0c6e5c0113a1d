// The clip commands (KeyPose, DeleteKey, MoveKey, SetClipSettings): what they
// change, exact undo and redo (by saved bytes), texts, errors before any push,
// Document::setClip's checks and the clip across a rebuild.
#include <QSignalSpy>
#include <cmath>
#include <limits>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "base/Error.h"
#include "model/commands/DeleteKeyCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/MoveKeyCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/SetClipSettingsCommand.h"
#include "model/commands/SetPoseCommand.h"

namespace rigmesh::model::test {
namespace {

struct Animated {
    Document document;
    PartId id = kNoPart;
    std::vector<JointId> ends;

    Animated() {
        id = addPart(document, sharedStroke("biped"), QStringLiteral("Body"));
        document.undoStack()->clear();
        ends = endJoints(node().part->skeleton);
    }
    const PartNode& node() const { return document.part(id); }
    QUndoStack& stack() { return *document.undoStack(); }
    void pose(const Vec3& offset) {
        stack().push(new SetPoseCommand(document, id, dragged(node(), ends[0], offset), ends[0]));
    }
    void key(double time) { stack().push(new KeyPoseCommand(document, id, time)); }
};

TEST(ClipCommands, NewPartsHaveAnEmptyClipAt24Fps) {
    Animated a;
    EXPECT_EQ(a.node().clip.keyCount(), 0);
    EXPECT_EQ(a.node().clip.framesPerSecond(), 24.0);
    EXPECT_EQ(a.node().clip.interpolation, Interpolation::Linear);
    EXPECT_EQ(a.node().clip.mode, PlaybackMode::Hold);
}

TEST(ClipCommands, KeyPoseKeysTheCurrentPoseAndUndoes) {
    Animated a;
    const QByteArray empty = bytesOf(a.document);
    QSignalSpy changed(&a.document, &Document::partChanged);
    a.key(0.0);
    ASSERT_EQ(a.node().clip.keyCount(), 1);
    EXPECT_TRUE(identicalPoses(a.node().clip.key(0.0), a.node().pose));
    ASSERT_EQ(changed.count(), 1);
    EXPECT_EQ(changed[0][1].value<Document::Changes>(), Document::Changes(Document::Change::Clip));
    EXPECT_EQ(a.stack().text(0), QStringLiteral("Key Body at 0 s"));

    a.pose(Vec3(0.1, 0.2, 0.0));
    a.key(0.5);
    ASSERT_EQ(a.node().clip.keyCount(), 2);
    EXPECT_TRUE(identicalPoses(a.node().clip.key(0.5), a.node().pose));
    EXPECT_FALSE(identicalPoses(a.node().clip.key(0.5), a.node().clip.key(0.0)));
    const QByteArray keyed = bytesOf(a.document);

    while (a.stack().canUndo())
        a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), empty);
    while (a.stack().canRedo())
        a.stack().redo();
    EXPECT_EQ(bytesOf(a.document), keyed);
}

TEST(ClipCommands, KeyPoseReplacesAKeyWithinHalfAFrame) {
    Animated a;
    a.key(1.0);
    a.pose(Vec3(0.15, 0.0, 0.1));
    const QByteArray before = bytesOf(a.document);
    a.key(1.0 + 0.4 / 24.0);  // same frame at 24 fps
    ASSERT_EQ(a.node().clip.keyCount(), 1);
    EXPECT_EQ(a.node().clip.keyTimes()[0], 1.0 + 0.4 / 24.0);
    EXPECT_TRUE(identicalPoses(a.node().clip.keys().begin()->second, a.node().pose));
    a.key(1.0 + 0.6 / 24.0 + 0.4 / 24.0);  // the next frame: a new key
    EXPECT_EQ(a.node().clip.keyCount(), 2);
    a.stack().undo();
    a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), before);
}

TEST(ClipCommands, KeyingTheSameKeyAgainPushesNothing) {
    Animated a;
    a.key(0.25);
    const int count = a.stack().count();
    a.key(0.25);
    EXPECT_EQ(a.stack().count(), count);
}

TEST(ClipCommands, DeleteKeyRemovesTheKeyAndUndoes) {
    Animated a;
    a.key(0.0);
    a.pose(Vec3(0.1, 0.1, 0.1));
    a.key(1.0);
    const QByteArray two = bytesOf(a.document);
    a.stack().push(new DeleteKeyCommand(a.document, a.id, 1.0 + 0.2 / 24.0));
    ASSERT_EQ(a.node().clip.keyCount(), 1);
    EXPECT_TRUE(a.node().clip.hasKey(0.0));
    EXPECT_EQ(a.stack().text(a.stack().index() - 1),
              QStringLiteral("Delete key of Body at 1.00833 s"));
    a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), two);
    a.stack().redo();
    EXPECT_EQ(a.node().clip.keyCount(), 1);
}

TEST(ClipCommands, MoveKeyMovesAndReplacesAndUndoes) {
    Animated a;
    a.key(0.0);
    a.pose(Vec3(0.1, -0.1, 0.1));
    a.key(1.0);
    const rigmesh::Pose second = a.node().clip.key(1.0);
    const QByteArray before = bytesOf(a.document);
    a.stack().push(new MoveKeyCommand(a.document, a.id, 1.0, 2.0));
    ASSERT_EQ(a.node().clip.keyCount(), 2);
    EXPECT_TRUE(identicalPoses(a.node().clip.key(2.0), second));
    EXPECT_FALSE(a.node().clip.hasKey(1.0));
    a.stack().push(new MoveKeyCommand(a.document, a.id, 2.0, 0.0));  // replaces the key at 0
    ASSERT_EQ(a.node().clip.keyCount(), 1);
    EXPECT_TRUE(identicalPoses(a.node().clip.key(0.0), second));
    a.stack().undo();
    a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), before);
}

TEST(ClipCommands, ClipSettingsChangeAndUndo) {
    Animated a;
    a.key(0.0);
    const QByteArray before = bytesOf(a.document);
    a.stack().push(new SetClipSettingsCommand(a.document, a.id, 30.0, Interpolation::Smooth,
                                              PlaybackMode::Loop));
    EXPECT_EQ(a.node().clip.framesPerSecond(), 30.0);
    EXPECT_EQ(a.node().clip.interpolation, Interpolation::Smooth);
    EXPECT_EQ(a.node().clip.mode, PlaybackMode::Loop);
    EXPECT_EQ(a.node().clip.keyCount(), 1);
    EXPECT_EQ(a.stack().text(a.stack().index() - 1), QStringLiteral("Set clip of Body"));
    a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), before);
    const int count = a.stack().count();
    a.stack().push(new SetClipSettingsCommand(a.document, a.id, 24.0, Interpolation::Linear,
                                              PlaybackMode::Hold));  // no change: dropped
    EXPECT_EQ(a.stack().index(), count - 1);
}

TEST(ClipCommands, BadEditsThrowBeforeAnyPush) {
    Animated a;
    a.key(0.0);
    const QByteArray before = bytesOf(a.document);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(KeyPoseCommand(a.document, a.id, nan), rigmesh::Error);
    EXPECT_THROW(KeyPoseCommand(a.document, a.id + 10, 0.0), rigmesh::Error);
    EXPECT_THROW(DeleteKeyCommand(a.document, a.id, 0.5), rigmesh::Error);
    EXPECT_THROW(MoveKeyCommand(a.document, a.id, 0.5, 1.0), rigmesh::Error);
    EXPECT_THROW(MoveKeyCommand(a.document, a.id, 0.0, nan), rigmesh::Error);
    EXPECT_THROW(
        SetClipSettingsCommand(a.document, a.id, 0.0, Interpolation::Linear, PlaybackMode::Hold),
        rigmesh::Error);
    EXPECT_THROW(SetClipSettingsCommand(a.document, a.id, -std::log(0.0), Interpolation::Linear,
                                        PlaybackMode::Hold),
                 rigmesh::Error);
    EXPECT_EQ(bytesOf(a.document), before);
    EXPECT_EQ(a.stack().count(), 1);
}

TEST(ClipCommands, SetClipRejectsJointsTheSkeletonLacks) {
    Animated a;
    rigmesh::Clip clip;
    rigmesh::Pose pose;
    pose.setRotation(999999, Eigen::Quaterniond::Identity());
    clip.setKey(0.0, pose);
    EXPECT_THROW(a.document.setClip(a.id, clip), rigmesh::Error);
    EXPECT_EQ(a.node().clip.keyCount(), 0);
}

TEST(ClipCommands, RebuildKeepsTheKeysAndSettingsAndUndoRestoresThem) {
    Animated a;
    a.stack().push(new SetClipSettingsCommand(a.document, a.id, 12.0, Interpolation::Smooth,
                                              PlaybackMode::Loop));
    a.key(0.0);
    a.pose(Vec3(0.1, 0.1, 0.0));
    a.key(1.0);
    const rigmesh::Clip keyed = a.node().clip;
    const QByteArray before = bytesOf(a.document);
    BuildOptions options;
    options.smoothing = false;  // the same skeleton: every key is kept as it was
    a.stack().push(RebuildPartCommand::create(a.document, a.id, options).release());
    EXPECT_TRUE(identicalClips(a.node().clip, keyed));
    EXPECT_EQ(a.node().clip.framesPerSecond(), 12.0);
    EXPECT_EQ(a.node().clip.interpolation, Interpolation::Smooth);
    EXPECT_EQ(a.node().clip.mode, PlaybackMode::Loop);
    a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), before);
}

// Each key command used to keep two whole clips, so n key steps took
// O(n^2) time and memory (2,000 keys: 8.8 s). A command now keeps only the
// keys it changes, and undo/redo still give back the exact clips.
TEST(ClipCommands, KeyCommandsKeepOnlyTheKeysTheyChangeAndUndoExactly) {
    Animated a;
    for (int k = 0; k < 300; ++k) {
        if (k == 10 || k == 11)  // keys 10 and 11 hold different poses
            a.pose(Vec3(0.05 * k, 0.1, 0.0));
        a.key(k / 24.0);
    }
    const QByteArray keyed = bytesOf(a.document);

    auto* rekey = new KeyPoseCommand(a.document, a.id, 100 / 24.0 + 0.01);
    EXPECT_EQ(rekey->edit().removed.size(), 1u);
    EXPECT_EQ(rekey->edit().added.size(), 1u);
    a.stack().push(rekey);
    // Moving a key onto another replaces it: two keys out, one in.
    auto* move = new MoveKeyCommand(a.document, a.id, 10 / 24.0, 11 / 24.0);
    EXPECT_EQ(move->edit().removed.size(), 2u);
    EXPECT_EQ(move->edit().added.size(), 1u);
    a.stack().push(move);
    a.stack().push(new DeleteKeyCommand(a.document, a.id, 200 / 24.0));
    EXPECT_EQ(a.node().clip.keyCount(), 298);
    const QByteArray edited = bytesOf(a.document);

    for (int u = 0; u < 3; ++u)
        a.stack().undo();
    EXPECT_EQ(bytesOf(a.document), keyed);
    for (int r = 0; r < 3; ++r)
        a.stack().redo();
    EXPECT_EQ(bytesOf(a.document), edited);
}

TEST(ClipCommands, KeyTimesOutOfRangeAreRefusedBeforeAnyPush) {
    Animated a;
    EXPECT_THROW(KeyPoseCommand(a.document, a.id, 1e308), Error);
    a.key(0.0);
    EXPECT_THROW(MoveKeyCommand(a.document, a.id, 0.0, -1e7), Error);
    EXPECT_EQ(a.stack().count(), 1);
    EXPECT_EQ(a.node().clip.keyTimes(), (std::vector<double>{0.0}));
}

}  // namespace
}  // namespace rigmesh::model::test
