// Named clips per part: new, duplicate, rename, delete and the
// active clip as undoable commands with exact undo (by saved bytes), their
// refusals before any push, their recipe steps and replay, and the other
// clips carried through a rebuild.
#include <QSignalSpy>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "model/PartClips.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

struct TwoClips {
    Document document;
    PartId id = kNoPart;
    JointId end = kNoJoint;

    TwoClips() {
        id = addPart(document, sharedStroke("y_branch"), QStringLiteral("Y"));
        end = endJoints(node().part->skeleton).front();
        document.undoStack()->clear();
    }
    const PartNode& node() const { return document.part(id); }
    QUndoStack& stack() { return *document.undoStack(); }
    void poseAndKey(const Vec3& offset, double time) {
        stack().push(new SetPoseCommand(document, id, dragged(node(), end, offset), end));
        stack().push(new KeyPoseCommand(document, id, time));
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const rigmesh::Clip* clip : clipsOf(node()))
            out.push_back(clipName(*clip));
        return out;
    }
};

TEST(NamedClips, AnUnnamedClipIsCalledAction) {
    TwoClips t;
    EXPECT_EQ(t.names(), std::vector<std::string>{"Action"});
    EXPECT_EQ(findClip(t.node(), "Action"), &t.node().clip);
}

TEST(NamedClips, NewClipBecomesActiveAndUndoesExactly) {
    TwoClips t;
    t.poseAndKey(Vec3(0.1, 0.1, 0), 0.0);
    const QByteArray before = bytesOf(t.document);
    t.stack().push(ClipListCommand::create(t.document, t.id, "walk").release());
    EXPECT_EQ(clipName(t.node().clip), "walk");
    EXPECT_EQ(t.node().clip.keyCount(), 0);
    EXPECT_EQ(t.names(), (std::vector<std::string>{"Action", "walk"}));
    ASSERT_NE(findClip(t.node(), "Action"), nullptr);
    EXPECT_EQ(findClip(t.node(), "Action")->keyCount(), 1);
    const QByteArray after = bytesOf(t.document);
    t.stack().undo();
    EXPECT_EQ(bytesOf(t.document), before);
    t.stack().redo();
    EXPECT_EQ(bytesOf(t.document), after);
}

TEST(NamedClips, KeysGoIntoTheActiveClipOnly) {
    TwoClips t;
    t.poseAndKey(Vec3(0.1, 0.1, 0), 0.0);
    t.stack().push(ClipListCommand::create(t.document, t.id, "walk").release());
    t.poseAndKey(Vec3(-0.1, 0.2, 0), 0.5);
    t.poseAndKey(Vec3(0.1, -0.1, 0), 1.0);
    EXPECT_EQ(t.node().clip.keyCount(), 2);
    EXPECT_EQ(findClip(t.node(), "Action")->keyCount(), 1);
    t.stack().push(ClipListCommand::activate(t.document, t.id, "Action").release());
    EXPECT_EQ(t.node().clip.keyCount(), 1);
    EXPECT_EQ(findClip(t.node(), "walk")->keyCount(), 2);
}

TEST(NamedClips, ChoosingTheActiveClipAgainIsNoUndoStep) {
    TwoClips t;
    t.stack().push(ClipListCommand::create(t.document, t.id, "walk").release());
    const int steps = t.stack().count();
    t.stack().push(ClipListCommand::activate(t.document, t.id, "walk").release());
    t.stack().push(ClipListCommand::rename(t.document, t.id, "walk", "walk").release());
    EXPECT_EQ(t.stack().count(), steps);
}

TEST(NamedClips, DuplicateRenameAndDeleteUndoExactly) {
    TwoClips t;
    t.poseAndKey(Vec3(0.1, 0.1, 0), 0.0);
    t.poseAndKey(Vec3(-0.1, 0.1, 0), 1.0);
    std::vector<QByteArray> states{bytesOf(t.document)};
    t.stack().push(ClipListCommand::duplicate(t.document, t.id, "Action", "walk").release());
    EXPECT_EQ(clipName(t.node().clip), "walk");
    EXPECT_TRUE(identicalPoses(t.node().clip.key(1.0), findClip(t.node(), "Action")->key(1.0)));
    states.push_back(bytesOf(t.document));
    t.stack().push(ClipListCommand::rename(t.document, t.id, "Action", "idle").release());
    EXPECT_EQ(t.names(), (std::vector<std::string>{"idle", "walk"}));
    states.push_back(bytesOf(t.document));
    // Deleting the active clip activates the first other one by name.
    t.stack().push(ClipListCommand::remove(t.document, t.id, "walk").release());
    EXPECT_EQ(t.names(), std::vector<std::string>{"idle"});
    EXPECT_EQ(clipName(t.node().clip), "idle");
    states.push_back(bytesOf(t.document));
    for (int i = static_cast<int>(states.size()) - 2; i >= 0; --i) {
        t.stack().undo();
        EXPECT_EQ(bytesOf(t.document), states[i]) << i;
    }
    for (std::size_t i = 1; i < states.size(); ++i) {
        t.stack().redo();
        EXPECT_EQ(bytesOf(t.document), states[i]) << i;
    }
}

TEST(NamedClips, BadNamesAndTheLastClipAreRefusedBeforeAnyPush) {
    TwoClips t;
    t.stack().push(ClipListCommand::create(t.document, t.id, "walk").release());
    const QByteArray before = bytesOf(t.document);
    const int steps = t.stack().count();
    auto refused = [&](auto make, const std::string& words) {
        try {
            make();
            ADD_FAILURE() << "not refused: " << words;
        } catch (const Error& e) {
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    refused([&] { ClipListCommand::create(t.document, t.id, "walk"); }, "already has a clip");
    refused([&] { ClipListCommand::create(t.document, t.id, "Action"); }, "already has a clip");
    refused([&] { ClipListCommand::create(t.document, t.id, ""); }, "1 to 63");
    refused([&] { ClipListCommand::create(t.document, t.id, " walk"); }, "space");
    refused([&] { ClipListCommand::create(t.document, t.id, "a\tb"); }, "control");
    refused([&] { ClipListCommand::rename(t.document, t.id, "run", "x"); }, "no clip named");
    refused([&] { ClipListCommand::rename(t.document, t.id, "walk", "Action"); },
            "already has a clip");
    refused([&] { ClipListCommand::activate(t.document, t.id, "run"); }, "no clip named");
    refused([&] { ClipListCommand::duplicate(t.document, t.id, "walk", "walk"); },
            "already has a clip");
    t.stack().push(ClipListCommand::remove(t.document, t.id, "Action").release());
    refused([&] { ClipListCommand::remove(t.document, t.id, "walk"); }, "only this clip");
    t.stack().undo();
    EXPECT_EQ(bytesOf(t.document), before);
    EXPECT_EQ(t.stack().count(), steps + 1);  // the delete, undone; nothing refused was pushed
}

TEST(NamedClips, ClipStepsReplayToTheSameBytes) {
    TwoClips t;
    const QByteArray initial = bytesOf(t.document);
    t.poseAndKey(Vec3(0.1, 0.1, 0), 0.0);
    const QByteArray start = bytesOf(t.document);
    const int before = t.stack().index();
    runSteps(t.document,
             {{{"command", "new_clip"}, {"part", "Y"}, {"name", "walk"}},
              {{"command", "key"}, {"part", "Y"}, {"time", 0.25}},
              {{"command", "duplicate_clip"}, {"part", 0}, {"clip", "walk"}, {"name", "run"}},
              {{"command", "rename_clip"}, {"part", 0}, {"clip", "Action"}, {"name", "idle"}},
              {{"command", "active_clip"}, {"part", 0}, {"clip", "idle"}},
              {{"command", "delete_clip"}, {"part", 0}, {"clip", "run"}}});
    EXPECT_EQ(t.names(), (std::vector<std::string>{"idle", "walk"}));
    EXPECT_EQ(clipName(t.node().clip), "idle");
    EXPECT_EQ(findClip(t.node(), "walk")->keyCount(), 1);
    const QByteArray end = bytesOf(t.document);

    // The history written as a recipe replays to the same bytes.
    const nlohmann::json recipe = recipeFromHistory(t.document);
    while (t.stack().index() > before)
        t.stack().undo();
    ASSERT_EQ(bytesOf(t.document), start);
    Document replayed(DocumentFile::fromBytes(initial));
    RecipeRunner(replayed).run(recipe);
    EXPECT_EQ(bytesOf(replayed), end);
}

TEST(NamedClips, ClipStepErrorsNameTheProblem) {
    TwoClips t;
    EXPECT_NE(stepError(t.document, {{{"command", "delete_clip"}, {"part", 0}, {"clip", "Action"}}})
                  .find("only this clip"),
              std::string::npos);
    EXPECT_NE(
        stepError(t.document, {{{"command", "new_clip"}, {"part", 0}}}).find("needs \"name\""),
        std::string::npos);
}

TEST(NamedClips, EveryClipKeepsItsKeysThroughARebuild) {
    TwoClips t;
    t.poseAndKey(Vec3(0.1, 0.1, 0), 0.0);
    t.stack().push(ClipListCommand::create(t.document, t.id, "walk").release());
    t.poseAndKey(Vec3(-0.1, 0.1, 0), 0.5);
    const QByteArray before = bytesOf(t.document);
    BuildOptions options = t.node().options;
    options.smoothing = !options.smoothing;
    t.stack().push(RebuildPartCommand::create(t.document, t.id, options).release());
    EXPECT_EQ(t.node().clip.keyCount(), 1);
    ASSERT_NE(findClip(t.node(), "Action"), nullptr);
    EXPECT_EQ(findClip(t.node(), "Action")->keyCount(), 1);
    for (const rigmesh::Clip* clip : clipsOf(t.node()))
        for (const auto& [time, pose] : clip->keys())
            for (const auto& [joint, rotation] : pose.rotations)
                EXPECT_TRUE(t.node().part->skeleton.hasJoint(joint));
    t.stack().undo();
    EXPECT_EQ(bytesOf(t.document), before);
}

TEST(NamedClips, SetClipsRefusesTwoClipsOfOneName) {
    TwoClips t;
    rigmesh::Clip a, b;
    a.name = b.name = "walk";
    EXPECT_THROW(t.document.setClips(t.id, a, {b}), Error);
    rigmesh::Clip unnamed;
    rigmesh::Clip action;
    action.name = "Action";
    EXPECT_THROW(t.document.setClips(t.id, unnamed, {action}), Error);
}

}  // namespace
}  // namespace rigmesh::model::test
