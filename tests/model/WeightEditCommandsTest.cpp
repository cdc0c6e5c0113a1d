// Weight edits in the document: a paint stroke of many
// dabs is one undo step, bone locks are undoable and saved and keep their
// bone through painting and Smooth All, and hand-painted weights are marked
// so a rebuild can ask before discarding them; each replays headless.
#include "ModelTestSupport.h"
#include "PartWeightOf.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "model/commands/PaintWeightsCommand.h"
#include "model/commands/WeightCleanupCommand.h"
#include "model/recipe/RecipeFromHistory.h"
#include "part/PartJson.h"

namespace rigmesh::model::test {
namespace {

using testsupport::weightOf;

Document& bipedDocument(Document& document) {
    runSteps(document, {{{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("biped"))},
                         {"name", "biped"},
                         {"placement", {{"translation", {1.0, 0.0, 0.0}}}}}});
    return document;
}

nlohmann::json strokeStep(BoneId bone) {
    nlohmann::json dabs = nlohmann::json::array();
    for (int i = 0; i < 6; ++i)
        dabs.push_back({{"center", {1.0 + 0.05 * i, 1.0, 0.3}}, {"radius", 0.3}});
    return {{"command", "paint_weights"},
            {"part", "biped"},
            {"bone", bone},
            {"mode", "add"},
            {"falloff", "linear"},
            {"strength", 0.7},
            {"frontFacesOnly", {0.0, 0.0, 1.0}},
            {"dabs", dabs}};
}

TEST(PaintWeightsCommand, AStrokeOfManyDabsIsOneUndoStepMarkedPaintedAndReplayed) {
    Document document;
    bipedDocument(document);
    const QByteArray before = bytesOf(document);
    EXPECT_FALSE(document.parts()[0].part->weightsPainted);
    const BoneId bone = document.parts()[0].part->skeleton.bones().front().id;
    const int count = document.undoStack()->count();
    runSteps(document, {strokeStep(bone)});
    EXPECT_EQ(document.undoStack()->count(), count + 1) << "one stroke, one undo step";
    const Part& painted = *document.parts()[0].part;
    EXPECT_TRUE(painted.weightsPainted);
    EXPECT_TRUE(painted.validate().empty());
    const QByteArray after = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(after)), after)
        << "the painted mark is saved and read back";
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    document.undoStack()->redo();
    EXPECT_EQ(bytesOf(document), after);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
    // Both forms at once, or neither, are refused.
    nlohmann::json both = strokeStep(bone);
    both["center"] = {1.0, 1.0, 0.3};
    EXPECT_NE(stepError(document, {both}).find("either"), std::string::npos);
    EXPECT_EQ(bytesOf(document), after);
}

TEST(SetBoneLockCommand, ALockedBoneIsKeptByPaintAndSmoothAllAndTheLockIsUndoable) {
    Document document;
    bipedDocument(document);
    const Part original = *document.parts()[0].part;
    const BoneId locked = original.skeleton.bones()[1].id;
    const BoneId painted = original.skeleton.bones().front().id;
    const QByteArray before = bytesOf(document);
    runSteps(document, {{{"command", "lock_bone"}, {"part", "biped"}, {"bone", locked}}});
    EXPECT_EQ(document.parts()[0].part->lockedBones, std::set<BoneId>{locked});
    const QByteArray lockedBytes = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(lockedBytes)), lockedBytes);
    // Painting the locked bone itself is refused; nothing changes.
    nlohmann::json onLocked = strokeStep(locked);
    EXPECT_NE(stepError(document, {onLocked}).find("locked"), std::string::npos);
    EXPECT_EQ(bytesOf(document), lockedBytes);
    // Painting another bone and Smooth All keep the locked bone's weights.
    runSteps(
        document,
        {strokeStep(painted),
         {{"command", "smooth_weights"}, {"part", "biped"}, {"factor", 0.7}, {"iterations", 3}}});
    const Part& edited = *document.parts()[0].part;
    EXPECT_TRUE(edited.validate().empty());
    EXPECT_NE(edited.weights.perVertex, original.weights.perVertex);
    for (int v = 0; v < edited.mesh.vertexCount(); ++v)
        ASSERT_EQ(weightOf(edited, v, locked), weightOf(original, v, locked)) << v;
    const QByteArray after = bytesOf(document);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
    for (int i = 0; i < 3; ++i)
        document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    // Unlocking takes the lock off again.
    runSteps(document, {{{"command", "lock_bone"}, {"part", "biped"}, {"bone", locked}},
                        {{"command", "unlock_bone"}, {"part", "biped"}, {"bone", locked}}});
    EXPECT_TRUE(document.parts()[0].part->lockedBones.empty());
    EXPECT_NE(stepError(document, {{{"command", "lock_bone"}, {"part", "biped"}, {"bone", 999}}})
                  .find("no bone"),
              std::string::npos);
    EXPECT_NE(stepError(document,
                        {{{"command", "smooth_weights"}, {"part", "biped"}, {"iterations", 1e300}}})
                  .find("whole number"),
              std::string::npos);
}

TEST(SkinningEdits, APartNobodyPaintedSavesNoLockOrPaintFields) {
    Document document;
    bipedDocument(document);
    const std::string json = partToJson(*document.parts()[0].part).dump();
    EXPECT_EQ(json.find("lockedBones"), std::string::npos);
    EXPECT_EQ(json.find("weightsPainted"), std::string::npos);
    // A painted part written by this version reads back painted.
    Part part = *document.parts()[0].part;
    part.weightsPainted = true;
    part.lockedBones = {part.skeleton.bones()[0].id};
    const Part back = partFromJson(partToJson(part));
    EXPECT_TRUE(back.weightsPainted);
    EXPECT_EQ(back.lockedBones, part.lockedBones);
    // A lock on a bone the skeleton lacks is refused on reading.
    nlohmann::json broken = partToJson(part);
    broken["lockedBones"] = {12345};
    EXPECT_THROW(partFromJson(broken), Error);
}

// Recompute Weights after a stroke: one undo step, the weights no longer
// marked painted, undo gives the stroke back exactly, and the history
// replays headless to the same bytes.
TEST(RecomputeWeightsCommand, BoneHeatReplacesAStrokeAsOneUndoStepAndReplays) {
    Document document;
    bipedDocument(document);
    const BoneId bone = document.parts()[0].part->skeleton.bones().front().id;
    runSteps(document, {strokeStep(bone)});
    const QByteArray painted = bytesOf(document);
    const int count = document.undoStack()->count();
    runSteps(document, {{{"command", "recompute_weights"}, {"part", "biped"}}});
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    const Part& part = *document.parts()[0].part;
    EXPECT_FALSE(part.weightsPainted);
    EXPECT_TRUE(part.validate().empty());
    const QByteArray after = bytesOf(document);
    EXPECT_NE(after, painted);
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), painted);
    document.undoStack()->redo();
    EXPECT_EQ(bytesOf(document), after);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
    // Computed against one part, applied to another: refused, nothing changes.
    const auto stale = WeightCleanupCommand::recomputed(document.parts()[0].part);
    runSteps(document, {strokeStep(bone)});
    const QByteArray now = bytesOf(document);
    EXPECT_THROW(WeightCleanupCommand::fromRecomputed(document, document.parts()[0].id, stale),
                 Error);
    EXPECT_EQ(bytesOf(document), now);
}

}  // namespace
}  // namespace rigmesh::model::test
