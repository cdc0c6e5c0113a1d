// Auto-Rig in the model: a mesh imported without a rig gets a
// skeleton and weights as one undo step, the recipe step "rig" replays it,
// and a rigged part or a part changed meanwhile is refused, unchanged.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/RigPartCommand.h"
#include "model/recipe/RecipeFromHistory.h"

namespace rigmesh::model {
namespace {

using test::addPart;
using test::bytesOf;
using test::sharedStroke;

class RigPart : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(folder.isValid());
        Document source;
        addPart(source, sharedStroke("y_branch"), QStringLiteral("branch"));
        path = folder.filePath(QStringLiteral("branch.obj"));
        exportDocument(source, path.toStdString());
        auto import = ImportPartsCommand::create(document, path);
        id = import->partIds().front();
        document.undoStack()->push(import.release());
        ASSERT_EQ(document.part(id).part->skeleton.jointCount(), 0);
    }
    QTemporaryDir folder;
    QString path;
    Document document;
    PartId id = kNoPart;
};

TEST_F(RigPart, AnImportedMeshIsRiggedInOneUndoStep) {
    const QByteArray before = bytesOf(document);
    const int steps = document.undoStack()->count();
    auto command = RigPartCommand::create(document, id);
    EXPECT_TRUE(command->summary().contains(QStringLiteral("rigged with")));
    document.undoStack()->push(command.release());
    EXPECT_EQ(document.undoStack()->count(), steps + 1);
    const Part& rigged = *document.part(id).part;
    EXPECT_TRUE(rigged.validateSolid().empty());
    EXPECT_GE(rigged.skeleton.boneCount(), 3);  // a Y: three limbs at least
    EXPECT_EQ(rigged.weights.perVertex.size(), rigged.mesh.vertices.size());
    const QByteArray after = bytesOf(document);
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    document.undoStack()->redo();
    EXPECT_EQ(bytesOf(document), after);
}

TEST_F(RigPart, TheRigStepReplaysFromTheHistory) {
    document.undoStack()->push(RigPartCommand::create(document, id).release());
    const nlohmann::json recipe = recipeFromHistory(document);
    ASSERT_EQ(recipe["steps"].back()["command"], "rig");
    Document replayed;
    RecipeRunner(replayed).run(parseRecipe(recipe.dump(2), "history"));
    // Also checks that the flow does not depend on the heap's addresses
    // (autorig/DeterministicArena.h): this process has allocated plenty.
    EXPECT_EQ(bytesOf(replayed), bytesOf(document));
}

TEST_F(RigPart, ARiggedPartIsRefusedAndNothingChanges) {
    const PartId sketched = addPart(document, sharedStroke("tube"));
    const QByteArray before = bytesOf(document);
    try {
        RigPartCommand::create(document, sketched);
        FAIL() << "a sketched part was rigged again";
    } catch (const Error& error) {
        EXPECT_EQ(error.message().id, MessageId::AutoRigPartIsRigged);
    }
    EXPECT_EQ(bytesOf(document), before);
    EXPECT_NE(test::stepError(document, {{{"command", "rig"}, {"part", 1}}})
                  .find("already has a skeleton"),
              std::string::npos);
    EXPECT_EQ(bytesOf(document), before);
}

TEST_F(RigPart, AResultForAPartThatChangedMeanwhileIsRefused) {
    const RigPartCommand::Rigged rigged = RigPartCommand::rigged(document.part(id).part);
    document.undoStack()->undo();  // the import goes: the part with it
    EXPECT_THROW(RigPartCommand::fromRigged(document, id, rigged), Error);
    document.undoStack()->redo();  // the same part is back: the result fits again
    EXPECT_NO_THROW(RigPartCommand::fromRigged(document, id, rigged));
}

}  // namespace
}  // namespace rigmesh::model
