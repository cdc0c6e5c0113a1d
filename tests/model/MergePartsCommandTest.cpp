// MergePartsCommand (paper 3.2 in the document): one undo step that replaces
// the target by the merged part and removes the dragged one; undo gives both
// back byte for byte; a refused merge changes nothing; recipe steps name
// joints by id or by a point.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/commands/MergePartsCommand.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

// The camel body and a leg overlapping its front, as sketch steps.
void addBodyAndLeg(Document& document) {
    runSteps(document, {{{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("camel_body"))},
                         {"name", "body"}},
                        {{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("camel_leg"))},
                         {"name", "leg"},
                         {"placement", {{"translation", {1.7, -0.55, 0.3}}}}}});
}

TEST(MergePartsCommand, IsOneUndoStepAndUndoRestoresBothPartsExactly) {
    Document document;
    addBodyAndLeg(document);
    const QByteArray before = bytesOf(document);
    const int count = document.undoStack()->count();
    runSteps(document, {{{"command", "merge"},
                         {"part", "leg"},
                         {"into", "body"},
                         {"mode", "connect"},
                         {"joint", {1.7, -0.36, 0.3}},
                         {"target", 2}}});
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    ASSERT_EQ(document.partCount(), 1);
    const PartNode& merged = document.parts()[0];
    EXPECT_EQ(merged.name, QStringLiteral("body"));
    EXPECT_TRUE(merged.stroke.empty());  // no longer one sketch: not rebuildable
    EXPECT_TRUE(merged.part->validateSolid().empty());
    EXPECT_EQ(merged.part->skeleton.boneCount(), 4);  // 2 + 1 + the connecting bone
    const QByteArray after = bytesOf(document);

    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    document.undoStack()->redo();
    EXPECT_EQ(bytesOf(document), after);

    // The history replays to the same bytes (the step names joints by id).
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
}

TEST(MergePartsCommand, RefusedMergeLeavesTheDocumentUnchanged) {
    Document document;
    addBodyAndLeg(document);
    // Connect keeps the leg where it is (snap would move it onto the body).
    runSteps(document, {{{"command", "move"},
                         {"part", "leg"},
                         {"placement", {{"translation", {30.0, 0.0, 0.0}}}}}});
    const QByteArray before = bytesOf(document);
    const int count = document.undoStack()->count();
    const std::string error = stepError(document, {{{"command", "merge"},
                                                    {"part", "leg"},
                                                    {"into", "body"},
                                                    {"mode", "connect"},
                                                    {"joint", 0},
                                                    {"target", 0}}});
    EXPECT_NE(error.find("do not touch"), std::string::npos) << error;
    EXPECT_EQ(document.undoStack()->count(), count);
    EXPECT_EQ(bytesOf(document), before);
    EXPECT_NE(
        stepError(
            document,
            {{{"command", "merge"}, {"part", "leg"}, {"into", "leg"}, {"joint", 0}, {"target", 0}}})
            .find("itself"),
        std::string::npos);
    EXPECT_NE(stepError(document, {{{"command", "merge"},
                                    {"part", "leg"},
                                    {"into", "body"},
                                    {"mode", "weld"},
                                    {"joint", 0},
                                    {"target", 0}}})
                  .find("\"mode\""),
              std::string::npos);
}

TEST(MergePartsCommand, SplitPutsANewJointOnTheTargetBone) {
    Document document;
    addBodyAndLeg(document);
    const int bodyJoints = document.parts()[0].part->skeleton.jointCount();
    runSteps(document, {{{"command", "merge"},
                         {"part", "leg"},
                         {"into", "body"},
                         {"mode", "split"},
                         {"joint", {1.7, -0.36, 0.3}},
                         {"target", {1.7, 0.1, 0.0}}}});
    ASSERT_EQ(document.partCount(), 1);
    const Part& merged = *document.parts()[0].part;
    EXPECT_TRUE(merged.validateSolid().empty());
    // The body's joints, one new on its bone, and the leg's foot (its hip
    // became the new joint).
    EXPECT_EQ(merged.skeleton.jointCount(), bodyJoints + 1 + 1);
}

TEST(DocumentResolution, SketchesAfterTheFirstShareItsEdgeLength) {
    Document document;
    addBodyAndLeg(document);
    const BuildOptions& body = document.parts()[0].options;
    const BuildOptions& leg = document.parts()[1].options;
    EXPECT_GT(body.targetEdgeLength, 0.0);
    EXPECT_EQ(leg.targetEdgeLength, body.targetEdgeLength);
    // The small leg is coarser than when sketched alone (at 1/60 of its own
    // size). Not much coarser: a thin part is meshed at a fraction of its
    // radius whatever the document's edge length.
    Document alone;
    runSteps(alone, {{{"command", "sketch"},
                      {"points", pointsOf(sharedStroke("camel_leg"))},
                      {"name", "leg"}}});
    EXPECT_LT(document.parts()[1].part->mesh.vertexCount(),
              alone.parts()[0].part->mesh.vertexCount());
}

}  // namespace
}  // namespace rigmesh::model::test

namespace rigmesh::model::test {
namespace {

// CutPartCommand (paper 3.1): one step that turns one part into two; undo
// gives the part back byte for byte; the history replays exactly.
TEST(CutPartCommand, IsOneUndoStepAndUndoRestoresThePartExactly) {
    Document document;
    runSteps(
        document,
        {{{"command", "sketch"}, {"points", pointsOf(sharedStroke("tube"))}, {"name", "tube"}}});
    const QByteArray before = bytesOf(document);
    const int count = document.undoStack()->count();
    const PartId next = document.nextPartId();
    runSteps(document, {{{"command", "cut"},
                         {"part", "tube"},
                         {"plane", {{"point", {0.0, 0.0, 0.0}}, {"normal", {1.0, 0.2, 0.0}}}},
                         {"style", "sharp"},
                         {"names", {"left", "right"}}}});
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    ASSERT_EQ(document.partCount(), 2);
    EXPECT_EQ(document.parts()[0].name, QStringLiteral("left"));
    EXPECT_EQ(document.parts()[1].name, QStringLiteral("right"));
    EXPECT_EQ(document.parts()[1].id, next);
    for (const PartNode& node : document.parts()) {
        EXPECT_TRUE(node.part->validateSolid().empty());
        EXPECT_TRUE(node.stroke.empty());
    }
    const QByteArray after = bytesOf(document);
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    EXPECT_EQ(document.nextPartId(), next);
    document.undoStack()->redo();
    EXPECT_EQ(bytesOf(document), after);
    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), after);
}

TEST(CutPartCommand, AStrokeInAViewCutsAndABadCutChangesNothing) {
    Document document;
    runSteps(
        document,
        {{{"command", "sketch"}, {"points", pointsOf(sharedStroke("tube"))}, {"name", "tube"}}});
    const QByteArray before = bytesOf(document);
    // A stroke beside the part: refused, nothing changes.
    EXPECT_NE(stepError(document, {{{"command", "cut"},
                                    {"part", "tube"},
                                    {"stroke", {{40.0, -5.0}, {40.0, 5.0}}},
                                    {"view", {{"direction", {0, 0, -1}}, {"up", {0, 1, 0}}}}}})
                  .find("does not cross"),
              std::string::npos);
    EXPECT_EQ(bytesOf(document), before);
    // A vertical stroke across the middle, seen from the front.
    runSteps(document, {{{"command", "cut"},
                         {"part", "tube"},
                         {"stroke", {{0.05, -5.0}, {0.0, 5.0}}},
                         {"view", {{"direction", {0, 0, -1}}, {"up", {0, 1, 0}}}}}});
    ASSERT_EQ(document.partCount(), 2);
    EXPECT_EQ(document.parts()[1].name, QStringLiteral("tube cut"));
}

}  // namespace
}  // namespace rigmesh::model::test
