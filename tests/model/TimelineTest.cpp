// The document's timeline: the current frame (shown, saved, never
// an undo step), frame range and rate (a rate change keeps keys on their
// frames), moving keys together, copy/paste/delete at the cursor as one undo
// step each, auto-key, onion poses, and the file's version 2 with version 1
// files migrated.
#include <QSignalSpy>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "PoseDistance.h"
#include "PoseTestSupport.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "model/OnionSkin.h"
#include "model/PartClips.h"
#include "model/PoseChange.h"
#include "model/TimelineEdits.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/MoveKeysCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/commands/SetTimelineCommand.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

struct Keyed {
    Document document;
    PartId id = kNoPart;
    JointId end = kNoJoint;
    std::vector<rigmesh::Pose> poses;  // keyed at frames 0, 12, 24

    Keyed() {
        id = addPart(document, sharedStroke("y_branch"), QStringLiteral("Y"));
        end = endJoints(node().part->skeleton).front();
        for (int k = 0; k < 3; ++k) {
            pose(Vec3(0.05 * (k + 1), 0.1 * (k % 2 == 0 ? 1 : -1), 0));
            poses.push_back(node().pose);
            stack().push(new KeyPoseCommand(document, id, frameTime(12 * k)));
        }
    }
    const PartNode& node() const { return document.part(id); }
    QUndoStack& stack() { return *document.undoStack(); }
    double frameTime(int frame) const { return document.timeline().timeOfFrame(frame); }
    void pose(const Vec3& offset) {
        stack().push(new SetPoseCommand(document, id, dragged(node(), end, offset), end));
    }
    std::vector<double> frames() const {
        std::vector<double> out;
        for (double t : node().clip.keyTimes())
            out.push_back(std::round(t * document.timeline().framesPerSecond * 1e9) / 1e9);
        return out;
    }
};

using rigmesh::test::poseDistance;

TEST(Timeline, ChangingTheFrameShowsTheClipsPoseWithoutAnUndoStep) {
    Keyed k;
    k.stack().setClean();
    const int steps = k.stack().count();
    QSignalSpy frames(&k.document, &Document::currentFrameChanged);
    k.document.setCurrentFrame(12);
    EXPECT_LT(poseDistance(k.node().pose, k.poses[1]), 1e-12);
    k.document.setCurrentFrame(6);  // half way between the first two keys
    EXPECT_LT(poseDistance(k.node().pose, k.node().clip.evaluate(k.frameTime(6))), 1e-12);
    EXPECT_GT(poseDistance(k.node().pose, k.poses[0]), 1e-3);
    EXPECT_EQ(frames.count(), 2);
    EXPECT_EQ(k.stack().count(), steps);
    EXPECT_FALSE(k.document.isModified());
    EXPECT_THROW(k.document.setCurrentFrame(-1), Error);
    EXPECT_THROW(k.document.setCurrentFrame(kMaxFrame + 1), Error);
}

TEST(Timeline, AnUnkeyedPoseStaysUntilTheFrameChanges) {
    Keyed k;
    k.document.setCurrentFrame(6);
    k.pose(Vec3(-0.2, 0.0, 0.05));
    const rigmesh::Pose posed = k.node().pose;
    EXPECT_GT(poseDistance(posed, k.node().clip.evaluate(k.frameTime(6))), 1e-3);
    k.document.setCurrentFrame(7);
    EXPECT_LT(poseDistance(k.node().pose, k.node().clip.evaluate(k.frameTime(7))), 1e-12);
    k.document.setCurrentFrame(6);
    EXPECT_GT(poseDistance(k.node().pose, posed), 1e-3);  // gone, as in Blender
}

TEST(Timeline, AutoKeyKeysEachPoseChangeInOneUndoStep) {
    Keyed k;
    k.document.setCurrentFrame(6);
    k.document.setAutoKey(true);
    const int count = k.node().clip.keyCount();
    const QByteArray before = bytesOf(k.document);
    const rigmesh::Pose to = dragged(k.node(), k.end, Vec3(-0.2, 0.05, 0));
    pushPoseChange(k.document, k.id, new SetPoseCommand(k.document, k.id, to, k.end));
    EXPECT_EQ(k.node().clip.keyCount(), count + 1);
    EXPECT_TRUE(identicalPoses(k.node().clip.key(k.frameTime(6)), to));
    EXPECT_TRUE(k.stack().text(k.stack().index() - 1).endsWith(QStringLiteral(" and key")));
    k.stack().undo();
    EXPECT_EQ(bytesOf(k.document), before);
    k.document.setAutoKey(false);
    pushPoseChange(k.document, k.id, new SetPoseCommand(k.document, k.id, to, k.end));
    EXPECT_EQ(k.node().clip.keyCount(), count);
}

TEST(Timeline, MovingKeysTogetherIsOneStepAndUndoesExactly) {
    Keyed k;
    const QByteArray before = bytesOf(k.document);
    // The keys at 0 and 12 move by 12 frames: the first lands where the second
    // was, which moves on, and the key at 24 is replaced by the second.
    k.stack().push(
        new MoveKeysCommand(k.document, k.id, {k.frameTime(0), k.frameTime(12)}, k.frameTime(12)));
    EXPECT_EQ(k.frames(), (std::vector<double>{12, 24}));
    EXPECT_TRUE(identicalPoses(k.node().clip.key(k.frameTime(12)), k.poses[0]));
    EXPECT_TRUE(identicalPoses(k.node().clip.key(k.frameTime(24)), k.poses[1]));
    const QByteArray after = bytesOf(k.document);
    k.stack().undo();
    EXPECT_EQ(bytesOf(k.document), before);
    k.stack().redo();
    EXPECT_EQ(bytesOf(k.document), after);
    EXPECT_THROW(MoveKeysCommand(k.document, k.id, {k.frameTime(5)}, 1.0), Error);
    EXPECT_THROW(MoveKeysCommand(k.document, k.id, {k.frameTime(12)}, 2e6), Error);
}

// A key move previewed live (widgets/timeline/KeyDrag) is put back and
// pushed: the command's redo ends where the preview showed.
TEST(Timeline, APreviewedKeyMoveIsOneStepEndingWhereThePreviewShowed) {
    Keyed k;
    const QByteArray before = bytesOf(k.document);
    const std::vector<double> times{k.frameTime(24)};
    const ClipEdit edit = movedKeysEdit(k.node().clip, times, k.frameTime(6));
    k.document.editClip(k.id, edit);  // the live preview
    const QByteArray previewed = bytesOf(k.document);
    k.document.editClip(k.id, edit.inverse());  // put back on release
    k.stack().push(new MoveKeysCommand(k.document, k.id, times, k.frameTime(6)));
    EXPECT_EQ(bytesOf(k.document), previewed);
    EXPECT_EQ(k.frames(), (std::vector<double>{0, 12, 30}));
    k.stack().undo();
    EXPECT_EQ(bytesOf(k.document), before);
    k.stack().redo();
    EXPECT_EQ(bytesOf(k.document), previewed);
}

TEST(Timeline, CopyPasteAtTheCursorAndDeleteAreOneStepEach) {
    Keyed k;
    const QByteArray before = bytesOf(k.document);
    const KeySelection selected{{k.id, {k.frameTime(12), k.frameTime(24)}}};
    const KeyClipboard copied = copyKeys(k.document, selected);
    ASSERT_EQ(copied.keys.at(k.id).size(), 2u);
    k.document.setCurrentFrame(40);
    const int steps = k.stack().index();
    const KeySelection pasted = pasteKeys(k.document, copied);
    EXPECT_EQ(k.stack().index(), steps + 1);
    EXPECT_EQ(k.frames(), (std::vector<double>{0, 12, 24, 40, 52}));
    EXPECT_EQ(pasted.at(k.id),
              (std::set<double>{k.frameTime(40), k.frameTime(40) + k.frameTime(12)}));
    EXPECT_TRUE(identicalPoses(k.node().clip.key(k.frameTime(40)), k.poses[1]));
    EXPECT_TRUE(identicalPoses(k.node().clip.key(k.frameTime(52)), k.poses[2]));

    EXPECT_EQ(deleteKeys(k.document, pasted), 2);
    EXPECT_EQ(k.stack().index(), steps + 2);
    EXPECT_EQ(k.frames(), (std::vector<double>{0, 12, 24}));
    k.stack().undo();
    k.stack().undo();
    k.document.setCurrentFrame(0);
    EXPECT_EQ(k.frames(), (std::vector<double>{0, 12, 24}));
    EXPECT_EQ(DocumentFile::toBytes(k.document.contents()).size(), before.size());
}

TEST(Timeline, InsertKeysKeysTheSelectedPartOrEveryRiggedPart) {
    Keyed k;
    const PartId other = addPart(k.document, sharedStroke("tube"), QStringLiteral("T"));
    k.document.setCurrentFrame(30);
    EXPECT_EQ(insertKeys(k.document, k.id), 1);
    EXPECT_TRUE(k.node().clip.hasKey(k.frameTime(30)));
    EXPECT_EQ(k.document.part(other).clip.keyCount(), 0);
    const int steps = k.stack().index();
    k.document.setCurrentFrame(36);
    EXPECT_EQ(insertKeys(k.document, kNoPart), 2);
    EXPECT_EQ(k.stack().index(), steps + 1);  // one undo step for both parts
    EXPECT_TRUE(k.document.part(other).clip.hasKey(k.frameTime(36)));
}

TEST(Timeline, ARateChangeKeepsKeysOnTheirFramesAndUndoes) {
    Keyed k;
    k.stack().push(ClipListCommand::create(k.document, k.id, "walk").release());
    k.stack().push(new KeyPoseCommand(k.document, k.id, k.frameTime(10)));
    const QByteArray before = bytesOf(k.document);
    TimelineSettings settings = k.document.timeline();
    settings.framesPerSecond = 30;
    settings.endFrame = 90;
    k.stack().push(new SetTimelineCommand(k.document, settings));
    EXPECT_EQ(k.document.timeline(), settings);
    EXPECT_EQ(k.frames(), (std::vector<double>{10}));
    EXPECT_EQ(k.node().clip.framesPerSecond(), 30.0);
    const rigmesh::Clip* action = findClip(k.node(), "Action");
    ASSERT_NE(action, nullptr);
    EXPECT_EQ(action->keyTimes(), (std::vector<double>{0.0, 12.0 / 30, 24.0 / 30}));
    k.stack().undo();
    EXPECT_EQ(bytesOf(k.document), before);
    settings.startFrame = 90;
    EXPECT_THROW(SetTimelineCommand(k.document, settings), Error);
    settings = k.document.timeline();
    settings.framesPerSecond = 0.5;
    EXPECT_THROW(SetTimelineCommand(k.document, settings), Error);
}

TEST(Timeline, ARateChangeRetimesEachClipByItsOwnRate) {
    // A clip at 30 fps (as an import brings it) keyed on its frame 30 (1 s)
    // in a 24 fps timeline: the timeline going to 30 fps leaves the key on
    // frame 30 at 1 s. Retimed by the timeline's old rate it went to 0.8 s.
    Keyed k;  // keys at 0, 0.5 and 1 s
    runSteps(k.document, {{{"command", "clip_settings"}, {"part", 0}, {"frameRate", 30}}});
    ASSERT_EQ(k.node().clip.framesPerSecond(), 30.0);
    const std::vector<double> before = k.node().clip.keyTimes();
    ASSERT_EQ(before, (std::vector<double>{0.0, 0.5, 1.0}));
    TimelineSettings settings = k.document.timeline();
    settings.framesPerSecond = 30;
    settings.endFrame = 90;
    k.stack().push(new SetTimelineCommand(k.document, settings));
    EXPECT_EQ(k.node().clip.keyTimes(), before);
    // Going on to 60 fps, the keys stay on the clip's frames 0, 15 and 30.
    settings.framesPerSecond = 60;
    settings.endFrame = 180;
    k.stack().push(new SetTimelineCommand(k.document, settings));
    EXPECT_EQ(k.node().clip.keyTimes(), (std::vector<double>{0.0, 0.25, 0.5}));
}

TEST(Timeline, TimelineStepReplaysAndErrs) {
    Keyed k;
    runSteps(k.document, {{{"command", "timeline"}, {"start", 5}, {"end", 60}, {"frameRate", 25}}});
    EXPECT_EQ(k.document.timeline(), (TimelineSettings{5, 60, 25.0}));
    EXPECT_EQ(k.frames(), (std::vector<double>{0, 12, 24}));
    EXPECT_NE(
        stepError(k.document, {{{"command", "timeline"}, {"start", 2.5}}}).find("whole frame"),
        std::string::npos);
    EXPECT_NE(stepError(k.document, {{{"command", "timeline"}, {"end", 1}}}).find("end after"),
              std::string::npos);
}

TEST(Timeline, KeyStepsOfTheTimelineReplayToTheSameBytes) {
    Keyed k;
    const QByteArray start = bytesOf(k.document);
    const int first = k.stack().index();
    k.stack().push(new MoveKeysCommand(k.document, k.id, {k.frameTime(12)}, k.frameTime(3)));
    k.document.setCurrentFrame(30);
    pasteKeys(k.document, copyKeys(k.document, {{k.id, {k.frameTime(0)}}}));
    k.document.setCurrentFrame(30);  // the pose the pasted key gives, as the dock shows
    const QByteArray end = bytesOf(k.document);
    // A recipe of the whole history, replayed from nothing, at the same frame.
    const json recipe = recipeFromHistory(k.document);
    Document replayed;
    RecipeRunner(replayed).run(recipe);
    replayed.setCurrentFrame(30);
    EXPECT_EQ(bytesOf(replayed), end);
    // Undo gives the keys back (the pose the frame change showed stays: it
    // is no undo step).
    while (k.stack().index() > first)
        k.stack().undo();
    EXPECT_TRUE(identicalClips(k.node().clip, DocumentFile::fromBytes(start).parts[0].clip));
}

TEST(Timeline, OnionPosesAreTheKeysEitherSideOfTheFrame) {
    Keyed k;
    k.document.setCurrentFrame(6);
    OnionPoses onion = onionPoses(k.document, k.id);
    ASSERT_TRUE(onion.previous && onion.next);
    EXPECT_TRUE(identicalPoses(*onion.previous, k.poses[0]));
    EXPECT_TRUE(identicalPoses(*onion.next, k.poses[1]));
    k.document.setCurrentFrame(12);  // on a key: its neighbours
    onion = onionPoses(k.document, k.id);
    EXPECT_TRUE(identicalPoses(*onion.previous, k.poses[0]));
    EXPECT_TRUE(identicalPoses(*onion.next, k.poses[2]));
    k.document.setCurrentFrame(30);
    onion = onionPoses(k.document, k.id);
    EXPECT_TRUE(identicalPoses(*onion.previous, k.poses[2]));
    EXPECT_EQ(onion.next, nullptr);
}

// ---- The file ----

TEST(TimelineFile, TheTimelineClipsAndCurrentFrameRoundTrip) {
    Keyed k;
    k.stack().push(ClipListCommand::create(k.document, k.id, "walk").release());
    k.stack().push(new KeyPoseCommand(k.document, k.id, k.frameTime(5)));
    k.stack().push(new SetTimelineCommand(k.document, {3, 77, 30.0}));
    k.document.setCurrentFrame(17);
    const QByteArray bytes = bytesOf(k.document);
    EXPECT_EQ(documentJson(bytes)["version"], DocumentFile::kFormatVersion);
    const DocumentContents loaded = DocumentFile::fromBytes(bytes);
    EXPECT_EQ(loaded.timeline, (TimelineSettings{3, 77, 30.0}));
    EXPECT_EQ(loaded.currentFrame, 17);
    ASSERT_EQ(loaded.parts.size(), 1u);
    EXPECT_EQ(clipName(loaded.parts[0].clip), "walk");
    ASSERT_EQ(loaded.parts[0].otherClips.size(), 1u);
    EXPECT_TRUE(identicalClips(loaded.parts[0].otherClips[0], k.node().otherClips[0]));
    EXPECT_EQ(DocumentFile::toBytes(loaded), bytes);
}

TEST(TimelineFile, AVersion2FileIsMigrated) {
    Keyed k;
    // Version 2 (per-bone poses, before the timeline) wrote exactly this,
    // without the timeline and other clips.
    json root = documentJson(bytesOf(k.document));
    root["version"] = 2;
    root.erase("timeline");
    for (json& part : root["parts"])
        part.erase("otherClips");
    const DocumentContents loaded = DocumentFile::fromBytes(documentBytes(root));
    EXPECT_EQ(loaded.currentFrame, 0);
    EXPECT_EQ(loaded.timeline.startFrame, 0);
    EXPECT_EQ(loaded.timeline.endFrame, 48);
    EXPECT_EQ(loaded.timeline.framesPerSecond, 24.0);
    ASSERT_EQ(loaded.parts.size(), 1u);
    EXPECT_TRUE(identicalClips(loaded.parts[0].clip, k.node().clip));
    EXPECT_TRUE(loaded.parts[0].otherClips.empty());

    // A version 2 clip at 30 fps with a key at 3 s: the rate is taken and the
    // range reaches the key.
    root["parts"][0]["clip"]["framesPerSecond"] = 30.0;
    root["parts"][0]["clip"]["keys"][2]["time"] = 3.0;
    const DocumentContents thirty = DocumentFile::fromBytes(documentBytes(root));
    EXPECT_EQ(thirty.timeline.framesPerSecond, 30.0);
    EXPECT_EQ(thirty.timeline.endFrame, 90);
}

TEST(TimelineFile, KeysOfOlderFilesBeforeZeroMoveToStartAtZero) {
    // Older versions let keys go below 0 s (a key at -1 s, keys moved by
    // -0.25 s); such a clip moves as a whole, as an import's does.
    Keyed k;  // keys at 0, 0.5 and 1 s
    json root = documentJson(bytesOf(k.document));
    root["parts"][0]["clip"]["keys"][0]["time"] = -1.0;
    const DocumentContents loaded = DocumentFile::fromBytes(documentBytes(root));
    ASSERT_EQ(loaded.parts.size(), 1u);
    EXPECT_EQ(loaded.parts[0].clip.keyTimes(), (std::vector<double>{0.0, 1.5, 2.0}));
    // Clips that start at 0 s or later keep their times exactly.
    EXPECT_EQ(DocumentFile::fromBytes(bytesOf(k.document)).parts[0].clip.keyTimes(),
              k.node().clip.keyTimes());
}

TEST(TimelineFile, BadTimelinesAndClipNamesAreCorrupt) {
    Keyed k;
    k.stack().push(ClipListCommand::create(k.document, k.id, "walk").release());
    const json good = documentJson(bytesOf(k.document));
    auto message = [](const json& root) {
        try {
            DocumentFile::fromBytes(documentBytes(root));
        } catch (const DocumentFileError& e) {
            return std::string(e.what());
        }
        return std::string("loaded");
    };
    json bad = good;
    bad["timeline"]["endFrame"] = -3;
    EXPECT_NE(message(bad).find("timeline"), std::string::npos);
    bad = good;
    bad["timeline"]["framesPerSecond"] = 0.0;
    EXPECT_NE(message(bad).find("frame rate"), std::string::npos);
    bad = good;
    bad["timeline"]["currentFrame"] = kMaxFrame + 1;
    EXPECT_NE(message(bad).find("Frame"), std::string::npos);
    bad = good;
    bad.erase("timeline");
    EXPECT_NE(message(bad).find("timeline"), std::string::npos);
    bad = good;
    bad["parts"][0]["otherClips"][0]["name"] = "walk";  // the active clip's name
    EXPECT_NE(message(bad).find("two clips named"), std::string::npos);
    bad = good;
    bad["parts"][0]["clip"]["interpolation"] = "cubic";
    EXPECT_NE(message(bad).find("unknown clip interpolation"), std::string::npos);
    bad = good;
    bad["version"] = DocumentFile::kFormatVersion + 1;
    EXPECT_NE(message(bad).find("newer"), std::string::npos);
}

}  // namespace
}  // namespace rigmesh::model::test
