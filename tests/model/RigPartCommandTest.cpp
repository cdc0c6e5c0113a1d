// Auto-Rig in the model: a mesh imported without a rig gets a
// skeleton and weights as one undo step, the recipe step "rig" replays it,
// and a rigged part or a part changed meanwhile is refused, unchanged.
#include <gtest/gtest.h>

#include <QFile>
#include <QTemporaryDir>
#include <QTextStream>
#include <nlohmann/json.hpp>

#include "ModelTestSupport.h"
#include "RecipeTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshPrimitives.h"
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

// Two objects in one OBJ (a body and a separate cap above it) import as
// two parts; rigging them together makes one part of both meshes, and undo
// gives both back where they were.
TEST_F(RigPart, PartsFromOneFileAreRiggedAsOneFigureAndUndoGivesThemBack) {
    const QString twoPath = folder.filePath(QStringLiteral("two.obj"));
    {
        QFile file(twoPath);
        ASSERT_TRUE(file.open(QIODevice::WriteOnly));
        QTextStream out(&file);
        const TriMesh body = makeCylinderTube(16, 16, 0.3, 2.0);
        const TriMesh cap = makeIcosphere(2, 0.35);
        out << "o body\n";
        for (const Vec3& v : body.vertices)
            out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        for (const auto& f : body.faces)
            out << "f " << f[0] + 1 << ' ' << f[1] + 1 << ' ' << f[2] + 1 << '\n';
        out << "o cap\n";
        for (const Vec3& v : cap.vertices)
            out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() + 1.25 << '\n';
        const int offset = body.vertexCount() + 1;
        for (const auto& f : cap.faces)
            out << "f " << f[0] + offset << ' ' << f[1] + offset << ' ' << f[2] + offset << '\n';
    }
    Document two;
    auto import = ImportPartsCommand::create(two, twoPath);
    const std::vector<PartId> ids = import->partIds();
    two.undoStack()->push(import.release());
    ASSERT_EQ(ids.size(), 2u);
    const int vertices =
        two.part(ids[0]).part->mesh.vertexCount() + two.part(ids[1]).part->mesh.vertexCount();
    const QByteArray before = bytesOf(two);
    auto command = RigPartCommand::create(two, ids);
    EXPECT_EQ(command->recipeStep()["parts"], nlohmann::json::array({0, 1}));
    two.undoStack()->push(command.release());
    ASSERT_EQ(two.partCount(), 1);
    const Part& rigged = *two.part(ids[0]).part;
    EXPECT_EQ(rigged.mesh.vertexCount(), vertices);
    EXPECT_TRUE(rigged.validate().empty());
    EXPECT_GE(rigged.skeleton.boneCount(), 1);
    const QByteArray after = bytesOf(two);
    two.undoStack()->undo();
    EXPECT_EQ(bytesOf(two), before);
    two.undoStack()->redo();
    EXPECT_EQ(bytesOf(two), after);
}

// An open mesh (a statue open at the bottom, made in Blender) is rigged on a
// wrapped proxy but keeps its own open surface; the document it is saved in
// opens again with that part as it was (model/DocumentFile.cpp checks only
// surfaces made here for being closed).
TEST(RigPartOpenMesh, ADocumentWithARiggedOpenMeshOpensAgainUnchanged) {
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    Document document;
    auto import = ImportPartsCommand::create(
        document, QStringLiteral(RIGMESH_TEST_DATA "/autorig/statue.obj"));
    const PartId id = import->partIds().front();
    document.undoStack()->push(import.release());
    document.undoStack()->push(RigPartCommand::create(document, id).release());
    const Part& rigged = *document.part(id).part;
    ASSERT_GT(rigged.skeleton.boneCount(), 0);
    ASSERT_FALSE(rigged.validateSolid().empty()) << "the statue should stay open";
    EXPECT_TRUE(rigged.validate().empty());

    const QString path = folder.filePath(QStringLiteral("statue.rigmesh"));
    DocumentFile::save(document, path);
    std::unique_ptr<Document> loaded;
    ASSERT_NO_THROW(loaded = DocumentFile::load(path));
    EXPECT_EQ(bytesOf(*loaded), bytesOf(document));
    EXPECT_TRUE(loaded->part(id).part->surfaceFromFile);
}

// Several imported meshes rigged as one figure (HUMAN.blend of Debian's
// assimp-testmodels: an open body and a second mesh): the joined part keeps
// the flag that its surface is the file's, so the saved document opens.
TEST(RigPartOpenMesh, SeveralOpenMeshesRiggedAsOneOpenAgainUnchanged) {
    QTemporaryDir folder;
    ASSERT_TRUE(folder.isValid());
    Document document;
    auto import = ImportPartsCommand::create(
        document, QStringLiteral("/usr/share/assimp/models/BLEND/HUMAN.blend"));
    const std::vector<PartId> ids = import->partIds();
    ASSERT_GE(ids.size(), 2u);
    document.undoStack()->push(import.release());
    document.undoStack()->push(RigPartCommand::create(document, ids).release());
    const Part& rigged = *document.part(ids.front()).part;
    ASSERT_GT(rigged.skeleton.boneCount(), 0);
    ASSERT_FALSE(rigged.validateSolid().empty()) << "the body should stay open";

    const QString path = folder.filePath(QStringLiteral("human.rigmesh"));
    DocumentFile::save(document, path);
    std::unique_ptr<Document> loaded;
    ASSERT_NO_THROW(loaded = DocumentFile::load(path));
    EXPECT_EQ(bytesOf(*loaded), bytesOf(document));
    EXPECT_TRUE(loaded->part(ids.front()).part->surfaceFromFile);
}

}  // namespace
}  // namespace rigmesh::model
