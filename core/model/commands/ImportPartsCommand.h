// Imports the rigged parts of a file (glTF, FBX, COLLADA, or anything Assimp
// reads) as new parts: mesh, skeleton, skin weights, and the file's clip on
// the part it animates. The file is read in create(), before anything is
// pushed. A static mesh without a usable skeleton is refused with a message
// that says so: rigging imported meshes is not available yet.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <memory>
#include <vector>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class ImportPartsCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(ImportPartsCommand)
  public:
    // Throws rigmesh::Error (unreadable, unsupported, or not rigged).
    static std::unique_ptr<ImportPartsCommand> create(Document& document, const QString& path);
    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    std::vector<PartId> partIds() const;

  private:
    ImportPartsCommand(Document& document, QString path, std::vector<PartNode> nodes);
    Document& document_;
    QString path_;
    std::vector<PartNode> nodes_;
};

}  // namespace rigmesh::model
