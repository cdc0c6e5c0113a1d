// File > Import and the recipe's "import" step: rigged parts from a file come
// in as parts (one undo step), a static mesh is refused with a clear message.
#include <gtest/gtest.h>

#include <QTemporaryDir>
#include <nlohmann/json.hpp>
#include <set>

#include "ModelTestSupport.h"
#include "base/Error.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/recipe/RecipeRunner.h"

namespace rigmesh::model {
namespace {

using test::addPart;
using test::bytesOf;
using test::sharedStroke;

class ImportParts : public testing::Test {
  protected:
    void SetUp() override {
        ASSERT_TRUE(folder.isValid());
        addPart(source, sharedStroke("y_branch"));
        path = folder.filePath(QStringLiteral("y.glb")).toStdString();
        exportDocument(source, path);
    }
    QTemporaryDir folder;
    Document source;
    std::string path;
};

TEST_F(ImportParts, RiggedFileComesInAsPartsInOneUndoStep) {
    Document document;
    const QByteArray before = bytesOf(document);
    auto command = ImportPartsCommand::create(document, QString::fromStdString(path));
    document.undoStack()->push(command.release());
    ASSERT_EQ(document.partCount(), 1);
    const Part& imported = *document.parts().front().part;
    const Part& original = *source.parts().front().part;
    EXPECT_EQ(imported.skeleton.boneCount(), original.skeleton.boneCount());
    EXPECT_EQ(imported.weights.perVertex.size(), imported.mesh.vertices.size());
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
    document.undoStack()->redo();
    EXPECT_EQ(document.partCount(), 1);
}

TEST_F(ImportParts, ImportedPartSurvivesSaveAndLoadExactly) {
    Document document;
    document.undoStack()->push(
        ImportPartsCommand::create(document, QString::fromStdString(path)).release());
    const QByteArray saved = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(saved)), saved);
}

TEST_F(ImportParts, BlenderRigKeepsItsBoneNamesAndActionThroughSaveAndLoad) {
    Document document;
    document.undoStack()->push(
        ImportPartsCommand::create(document, QStringLiteral(RIGMESH_TEST_DATA) +
                                                 QStringLiteral("/blender_rig/capsule.glb"))
            .release());
    ASSERT_EQ(document.partCount(), 1);
    const DocumentContents loaded = DocumentFile::fromBytes(bytesOf(document));
    ASSERT_EQ(loaded.parts.size(), 1u);
    const PartNode& node = loaded.parts.front();
    std::set<std::string> names;
    for (const auto& [bone, name] : node.part->boneNames)
        names.insert(name);
    EXPECT_EQ(names, (std::set<std::string>{"Lower", "Middle", "Upper"}));
    EXPECT_EQ(node.clip.name, "Wave");
}

TEST_F(ImportParts, StaticMeshComesInUnriggedAndSaysSo) {
    const std::string obj = folder.filePath(QStringLiteral("y.obj")).toStdString();
    exportDocument(source, obj);
    Document document;
    const QByteArray before = bytesOf(document);
    auto command = ImportPartsCommand::create(document, QString::fromStdString(obj));
    EXPECT_EQ(command->unrigged(), 1);
    document.undoStack()->push(command.release());
    ASSERT_EQ(document.partCount(), 1);
    const PartNode& node = document.parts().front();
    EXPECT_EQ(node.part->skeleton.jointCount(), 0);
    EXPECT_EQ(node.part->mesh.faceCount(), source.parts().front().part->mesh.faceCount());
    // It saves and reopens exactly.
    const QByteArray saved = bytesOf(document);
    EXPECT_EQ(DocumentFile::toBytes(DocumentFile::fromBytes(saved)), saved);
    // Rigged formats refuse it with a reason; OBJ takes it.
    try {
        exportDocument(document, folder.filePath(QStringLiteral("again.glb")).toStdString());
        FAIL() << "an unrigged part was exported to glTF";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("not rigged yet"), std::string::npos)
            << error.what();
    }
    ExportOptions posed;
    posed.restPose = false;
    EXPECT_NO_THROW(exportDocument(
        document, folder.filePath(QStringLiteral("again.obj")).toStdString(), posed));
    document.undoStack()->undo();
    EXPECT_EQ(bytesOf(document), before);
}

TEST_F(ImportParts, RecipeImportStepAddsTheFilesParts) {
    Document document;
    RecipeRunner runner(document, folder.path().toStdString());
    runner.run(nlohmann::json{{"format", "rigmesh-recipe"},
                              {"version", 1},
                              {"steps", {{{"command", "import"}, {"file", "y.glb"}}}}});
    EXPECT_EQ(document.partCount(), 1);
}

}  // namespace
}  // namespace rigmesh::model
