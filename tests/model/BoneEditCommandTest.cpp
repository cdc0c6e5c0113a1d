// Split and delete a bone in the document (paper 3.3): a straight leg gets a
// knee and loses it again, each one undo step that undo takes back byte for
// byte, and the history replays exactly.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

TEST(BoneEditCommand, AStraightLegGetsAKneeAndLosesItInOneStepEach) {
    Document document;
    runSteps(document, {{{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("camel_leg"))},
                         {"name", "leg"}}});
    ASSERT_EQ(document.parts()[0].part->skeleton.boneCount(), 1);
    const QByteArray straight = bytesOf(document);
    const int count = document.undoStack()->count();
    // The knee: the leg's bone split a little below its middle.
    runSteps(document, {{{"command", "split_bone"}, {"part", "leg"}, {"at", {0.0, -1.8, 0.0}}}});
    EXPECT_EQ(document.undoStack()->count(), count + 1);
    const Part& kneed = *document.parts()[0].part;
    EXPECT_EQ(kneed.skeleton.boneCount(), 2);
    EXPECT_TRUE(kneed.validateSolid().empty());
    const QByteArray withKnee = bytesOf(document);

    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), withKnee);

    // Delete the lower bone again (the one nearest the foot).
    runSteps(document, {{{"command", "delete_bone"}, {"part", "leg"}, {"at", {0.0, -3.2, 0.0}}}});
    EXPECT_EQ(document.parts()[0].part->skeleton.boneCount(), 1);
    EXPECT_TRUE(document.parts()[0].part->validateSolid().empty());
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), withKnee);
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), straight);
}

TEST(BoneEditCommand, RefusedEditsChangeNothing) {
    Document document;
    runSteps(document, {{{"command", "sketch"},
                         {"points", pointsOf(sharedStroke("camel_leg"))},
                         {"name", "leg"}}});
    const QByteArray before = bytesOf(document);
    EXPECT_NE(stepError(document, {{{"command", "delete_bone"}, {"part", "leg"}, {"bone", 0}}})
                  .find("only one"),
              std::string::npos);
    EXPECT_NE(stepError(document, {{{"command", "split_bone"}, {"part", "leg"}, {"bone", 42}}})
                  .find("no bone 42"),
              std::string::npos);
    EXPECT_EQ(bytesOf(document), before);
}

}  // namespace
}  // namespace rigmesh::model::test
