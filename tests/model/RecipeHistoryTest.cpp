// The undo history as a recipe: every command describes itself as a step,
// and a document built by random commands (undos included), written as a
// recipe, read back as text and replayed by the runner into a new document
// gives the same file bytes.
#include <map>
#include <random>

#include "ModelTestSupport.h"
#include "PoseTestSupport.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "model/commands/DeleteKeyCommand.h"
#include "model/commands/DeletePartCommand.h"
#include "model/commands/KeyPoseCommand.h"
#include "model/commands/MoveKeyCommand.h"
#include "model/commands/MovePartCommand.h"
#include "model/commands/RebuildPartCommand.h"
#include "model/commands/RenamePartCommand.h"
#include "model/commands/ResetPoseCommand.h"
#include "model/commands/SetClipSettingsCommand.h"
#include "model/commands/SetJointPinnedCommand.h"
#include "model/commands/SetPartVisibleCommand.h"
#include "model/commands/SetPoseCommand.h"
#include "model/preview/PosePreview.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

using nlohmann::json;

// Replays `recipe` (after a trip through its text) into a new document.
QByteArray replayed(const json& recipe) {
    Document document;
    RecipeRunner(document).run(parseRecipe(recipe.dump(2), "history"));
    return bytesOf(document);
}

class RandomHistory {
  public:
    explicit RandomHistory(unsigned seed) : rng_(seed) {}

    void step(Document& document) {
        QUndoStack& stack = *document.undoStack();
        const int parts = document.partCount();
        const int action = parts == 0 ? 0 : pick(0, 15);
        switch (action) {
            case 0:
                if (parts < 4) {
                    Placement placement;
                    placement.translation = Vec3(real(), real(), real());
                    stack.push(CreatePartCommand::create(
                                   document, testStrokes()[pick(0, 3)],
                                   pick(0, 1) ? QString() : QStringLiteral("P%1").arg(pick(0, 9)),
                                   {}, placement)
                                   .release());
                }
                return;
            case 1:
                if (parts > 1)
                    stack.push(new DeletePartCommand(document, randomPart(document)));
                return;
            case 2:
                stack.push(new RenamePartCommand(document, randomPart(document),
                                                 QStringLiteral("Name \"%1\"").arg(pick(0, 99))));
                return;
            case 3: {  // moves, merging when the same part moves again
                if (!document.contains(lastMoved_) || pick(0, 2) == 0)
                    lastMoved_ = randomPart(document);
                Placement p = document.part(lastMoved_).placement;
                p.translation += Vec3(real(), real(), real()) / 3.0;
                p.rotation = (p.rotation * Eigen::Quaterniond(Eigen::AngleAxisd(
                                               real(), Vec3(real(), 1.0, real()).normalized())))
                                 .normalized();
                stack.push(new MovePartCommand(document, lastMoved_, p));
                return;
            }
            case 4: {
                const PartId id = randomPart(document);
                stack.push(new SetPartVisibleCommand(document, id, !document.part(id).visible));
                return;
            }
            case 5: {
                BuildOptions options;
                options.targetEdgeLength = std::array{0.0, 0.15}[pick(0, 1)];
                options.smoothing = pick(0, 1) == 1;
                stack.push(
                    RebuildPartCommand::create(document, randomPart(document), options).release());
                return;
            }
            case 6:
            case 7:
                drag(document, false);
                return;
            case 8:
                drag(document, true);
                return;
            case 9: {
                const PartId id = randomPart(document);
                const Skeleton& skeleton = document.part(id).part->skeleton;
                const JointId joint = skeleton.joints()[pick(0, skeleton.jointCount() - 1)].id;
                stack.push(new SetJointPinnedCommand(
                    document, id, joint, !document.part(id).pinnedJoints.contains(joint)));
                return;
            }
            case 10:
                stack.push(new ResetPoseCommand(document, randomPart(document)));
                return;
            case 11:
            case 12:
                stack.push(new KeyPoseCommand(document, randomPart(document), pick(0, 8) / 4.0));
                return;
            case 13: {  // delete or move a key of a part that has keys
                const PartId id = randomPart(document);
                const std::vector<double> times = document.part(id).clip.keyTimes();
                if (times.empty())
                    return;
                const double time = times[pick(0, int(times.size()) - 1)];
                if (pick(0, 1))
                    stack.push(new DeleteKeyCommand(document, id, time));
                else
                    stack.push(new MoveKeyCommand(document, id, time, time + 0.1 * real()));
                return;
            }
            case 14:
                stack.push(new SetClipSettingsCommand(
                    document, randomPart(document), std::array{12.0, 24.0, 29.97}[pick(0, 2)],
                    pick(0, 1) ? Interpolation::Smooth : Interpolation::Linear,
                    pick(0, 1) ? PlaybackMode::Loop : PlaybackMode::Hold));
                return;
            default:  // step back: the undone command drops out of the history
                if (stack.canUndo())
                    stack.undo();
                return;
        }
    }

  private:
    // An IK drag step, often of the same joint again (merging); `live` drags
    // preview the pose first and commit it (model/preview/PosePreview.h), as the studio does.
    void drag(Document& document, bool live) {
        if (!document.contains(lastPosed_) || pick(0, 2) == 0) {
            lastPosed_ = randomPart(document);
            const std::vector<JointId> ends = endJoints(document.part(lastPosed_).part->skeleton);
            if (ends.empty())
                return;
            lastDragged_ = ends[pick(0, int(ends.size()) - 1)];
        }
        const PartNode& node = document.part(lastPosed_);
        const rigmesh::Pose pose = dragged(node, lastDragged_, 0.2 * Vec3(real(), real(), real()));
        if (live) {
            PosePreview preview(document, lastPosed_);
            preview.preview(pose);
            preview.commit(lastDragged_);
            return;
        }
        document.undoStack()->push(new SetPoseCommand(document, lastPosed_, pose, lastDragged_));
    }
    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    double real() { return std::uniform_real_distribution<double>(-1.0, 1.0)(rng_); }
    PartId randomPart(const Document& document) {
        return document.parts()[pick(0, document.partCount() - 1)].id;
    }

    std::mt19937 rng_;
    PartId lastMoved_ = kNoPart;
    PartId lastPosed_ = kNoPart;
    JointId lastDragged_ = kNoJoint;
};

class RecipeHistory : public ::testing::TestWithParam<unsigned> {};

TEST_P(RecipeHistory, RandomHistoryReplaysToTheSameBytes) {
    Document document;
    RandomHistory session(GetParam());
    for (int i = 0; i < 60; ++i)
        session.step(document);
    ASSERT_GT(document.partCount(), 0);
    const json recipe = recipeFromHistory(document);
    EXPECT_EQ(recipe["format"], "rigmesh-recipe");
    EXPECT_EQ(recipe["version"], RecipeFile::kFormatVersion);
    EXPECT_GE(recipe["steps"].size(), static_cast<std::size_t>(document.undoStack()->index()));
    std::map<std::string, int> kinds;
    for (const json& step : recipe["steps"])
        ++kinds[step["command"].get<std::string>()];
    for (const auto& [kind, count] : kinds)
        RecordProperty(kind, count);
    EXPECT_EQ(replayed(recipe), bytesOf(document));
}

INSTANTIATE_TEST_SUITE_P(Seeds, RecipeHistory, ::testing::Values(1u, 7u, 42u, 2024u, 31337u, 99u));

TEST(RecipeHistoryCases, EveryCommandWritesItsStep) {
    Document document;
    QUndoStack& stack = *document.undoStack();
    const PartId a = addPart(document, sharedStroke("biped"), QStringLiteral("A"));
    const PartId b = addPart(document, testStrokes()[0], QStringLiteral("B"));
    const std::vector<JointId> ends = endJoints(document.part(a).part->skeleton);
    const JointId end = ends[0];
    const JointId drag = ends[1];
    Placement moved;
    moved.translation = Vec3(0.5, 0.0, 0.0);
    stack.push(new MovePartCommand(document, b, moved));
    stack.push(new RenamePartCommand(document, b, QStringLiteral("C")));
    stack.push(new SetPartVisibleCommand(document, b, false));
    stack.push(new SetJointPinnedCommand(document, a, end, true));
    stack.push(
        new SetPoseCommand(document, a, dragged(document.part(a), drag, Vec3(0.1, 0.1, 0)), drag));
    stack.push(new KeyPoseCommand(document, a, 0.5));
    stack.push(new MoveKeyCommand(document, a, 0.5, 1.0));
    stack.push(
        new SetClipSettingsCommand(document, a, 30.0, Interpolation::Smooth, PlaybackMode::Loop));
    stack.push(new DeleteKeyCommand(document, a, 1.0));
    stack.push(new ResetPoseCommand(document, a));
    stack.push(new SetJointPinnedCommand(document, a, end, false));
    stack.push(RebuildPartCommand::create(document, b, {0.0, false}).release());
    stack.push(new DeletePartCommand(document, b));

    const json steps = recipeFromHistory(document)["steps"];
    std::vector<std::string> commands;
    for (const json& step : steps)
        commands.push_back(step["command"]);
    EXPECT_EQ(commands,
              (std::vector<std::string>{"sketch", "sketch", "move", "rename", "hide", "pin", "pose",
                                        "key", "move_key", "clip_settings", "delete_key",
                                        "reset_pose", "unpin", "rebuild", "delete"}));
    EXPECT_EQ(steps[6]["part"], 0);
    EXPECT_EQ(steps[6]["joint"], drag);
    EXPECT_EQ(steps[6]["complete"], true);
    EXPECT_EQ(steps[14]["part"], 1);
    EXPECT_EQ(replayed(recipeFromHistory(document)), bytesOf(document));
}

TEST(RecipeHistoryCases, UndoneCommandsAreLeftOut) {
    Document document;
    addPart(document, testStrokes()[0], QStringLiteral("A"));
    document.undoStack()->push(
        new RenamePartCommand(document, document.parts()[0].id, QStringLiteral("B")));
    document.undoStack()->undo();
    EXPECT_EQ(recipeFromHistory(document)["steps"].size(), 1u);
    EXPECT_EQ(replayed(recipeFromHistory(document)), bytesOf(document));
}

TEST(RecipeHistoryCases, MacrosGiveTheirChildrensSteps) {
    Document document;
    const PartId a = addPart(document, testStrokes()[0], QStringLiteral("A"));
    QUndoStack& stack = *document.undoStack();
    stack.beginMacro(QStringLiteral("Rename and hide"));
    stack.push(new RenamePartCommand(document, a, QStringLiteral("B")));
    stack.push(new SetPartVisibleCommand(document, a, false));
    stack.endMacro();
    const json steps = recipeFromHistory(document)["steps"];
    ASSERT_EQ(steps.size(), 3u);
    EXPECT_EQ(steps[1]["command"], "rename");
    EXPECT_EQ(steps[2]["command"], "hide");
    EXPECT_EQ(replayed(recipeFromHistory(document)), bytesOf(document));
}

TEST(RecipeHistoryCases, ForeignCommandsAreRefused) {
    Document document;
    document.undoStack()->push(new QUndoCommand(QStringLiteral("Something else")));
    EXPECT_THROW(recipeFromHistory(document), rigmesh::Error);
}

TEST(RecipeHistoryCases, SavedHistoryRunsFromTheFile) {
    Document document;
    addPart(document, sharedStroke("y_branch"), QStringLiteral("Y"));
    document.undoStack()->push(new KeyPoseCommand(document, document.parts()[0].id, 0.0));
    QTemporaryDir folder;
    const std::string path = (folder.path() + "/history.json").toStdString();
    saveHistoryAsRecipe(document, path);
    Document replay;
    runRecipeFile(replay, path);
    EXPECT_EQ(bytesOf(replay), bytesOf(document));
}

}  // namespace
}  // namespace rigmesh::model::test
