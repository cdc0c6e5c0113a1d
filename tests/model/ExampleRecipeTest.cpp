// The shipped example recipe runs with the model's runner (what `rigmesh run`
// does, without the executable): seven parts, one leg keyed three times, and
// its history written back as a recipe replays to the same bytes.
#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model::test {
namespace {

TEST(ExampleRecipe, CamelRunsAndItsHistoryReplaysExactly) {
    Document document;
    std::vector<RecipeStepReport> reports;
    runRecipeFile(document, std::string(RIGMESH_RESOURCES) + "/recipes/camel.json",
                  [&](const RecipeStepReport& report) { reports.push_back(report); });
    ASSERT_EQ(document.partCount(), 7);
    EXPECT_EQ(reports.size(), 13u);
    const PartNode& leg = document.parts()[3];
    EXPECT_EQ(leg.name, QStringLiteral("front_left"));
    ASSERT_EQ(leg.clip.keyCount(), 3);
    EXPECT_EQ(leg.clip.keyTimes(), (std::vector<double>{0.0, 0.5, 1.0}));
    EXPECT_FALSE(identicalPoses(leg.clip.key(0.0), leg.clip.key(0.5)));
    EXPECT_FALSE(identicalPoses(leg.clip.key(0.5), leg.clip.key(1.0)));
    EXPECT_EQ(leg.clip.interpolation, Interpolation::Smooth);
    EXPECT_EQ(leg.clip.mode, PlaybackMode::Loop);

    Document replay;
    RecipeRunner(replay).run(parseRecipe(recipeFromHistory(document).dump(), "history"));
    EXPECT_EQ(bytesOf(replay), bytesOf(document));
}

}  // namespace
}  // namespace rigmesh::model::test
