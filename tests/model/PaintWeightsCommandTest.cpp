// Weight painting in the document: a paint_weights step
// is one undo step that undo takes back byte for byte, painted weights are
// saved and read back, and a painting session replays headless.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

TEST(PaintWeightsCommand, ADabIsOneUndoStepSavedAndReplayed) {
    Document document;
    runSteps(document, {{{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("biped"))},
                         {"name", "biped"},
                         {"placement", {{"translation", {2.0, 0.0, 0.0}}}}},
                        {{"command", "key"}, {"part", "biped"}, {"time", 0.5}}});
    const QByteArray before = bytesOf(document);
    const Part& part = *document.parts()[0].part;
    const BoneId bone = part.skeleton.bones().front().id;
    const int count = document.undoStack()->count();
    // On the chest, in document coordinates (the part sits at x = 2).
    runSteps(document, {{{"command", "paint_weights"},
                         {"part", "biped"},
                         {"bone", bone},
                         {"mode", "add"},
                         {"center", {2.0, 1.0, 0.3}},
                         {"radius", 0.5},
                         {"strength", 0.8},
                         {"mirror", true}}});
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    const QByteArray painted = bytesOf(document);
    EXPECT_NE(painted, before);
    EXPECT_TRUE(document.parts()[0].part->validate().empty());
    EXPECT_EQ(document.parts()[0].clip.keyCount(), 1) << "painting keeps the keys";
    // Saved and read back exactly.
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(painted)), painted);
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    document.undoStack()->redo();
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), painted);
    // A locked bone cannot be painted; nothing changes.
    EXPECT_NE(stepError(document, {{{"command", "paint_weights"},
                                    {"part", "biped"},
                                    {"bone", bone},
                                    {"center", {2.0, 1.0, 0.3}},
                                    {"radius", 0.5},
                                    {"locked", {bone}}}})
                  .find("locked"),
              std::string::npos);
    EXPECT_EQ(bytesOf(document), painted);
}

}  // namespace
}  // namespace rigmesh::model::test

namespace rigmesh::model::test {
namespace {

TEST(WeightCleanupCommand, CleanAndLimitAreOneUndoStepEachAndReplay) {
    Document document;
    runSteps(
        document,
        {{{"command", "sketch"}, {"points", pointsOf(sharedStroke("biped"))}, {"name", "biped"}}});
    const QByteArray before = bytesOf(document);
    runSteps(document, {{{"command", "clean_weights"}, {"part", "biped"}, {"threshold", 0.1}},
                        {{"command", "limit_weights"}, {"part", "biped"}, {"influences", 2}},
                        {{"command", "normalize_weights"}, {"part", "biped"}}});
    for (const auto& list : document.parts()[0].part->weights.perVertex)
        EXPECT_LE(list.size(), 2u);
    EXPECT_TRUE(document.parts()[0].part->validate().empty());
    const QByteArray after = bytesOf(document);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
    for (int i = 0; i < 3; ++i)
        document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
}

}  // namespace
}  // namespace rigmesh::model::test
