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
    // The small leg gets far fewer vertices than the body (1,610 at its own
    // 1/60 of its size).
    EXPECT_LT(document.parts()[1].part->mesh.vertexCount(),
              document.parts()[0].part->mesh.vertexCount() / 3);
}

}  // namespace
}  // namespace rigmesh::model::test
