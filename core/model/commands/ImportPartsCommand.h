// Imports the parts of a file (glTF, FBX, COLLADA, OBJ, or anything Assimp
// reads) as new parts: mesh, skeleton, skin weights, and every clip of the
// file on the part it animates (the first one active). A static mesh without
// a usable skeleton comes in as an unrigged part: shown, moved, saved and
// exported as a mesh, posable once rigged (RigPartCommand; unrigged() says
// how many need it). The file is read in create() (or, by a background job,
// before fromRead()), before anything is pushed. When the file's animations
// run past the timeline's end, the timeline is extended to their last key
// (as Blender's importers set the scene's frame range), in the same undo step.
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
    // The command for parts already read (readImportedParts, e.g. by a
    // background job). Throws rigmesh::Error when there are none.
    static std::unique_ptr<ImportPartsCommand> fromRead(Document& document, const QString& path,
                                                        std::vector<PartNode> nodes);
    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;
    std::vector<PartId> partIds() const;
    // How many of the imported parts have no skeleton yet.
    int unrigged() const;

  private:
    ImportPartsCommand(Document& document, QString path, std::vector<PartNode> nodes);
    Document& document_;
    QString path_;
    std::vector<PartNode> nodes_;
    TimelineSettings timelineBefore_;
    TimelineSettings timelineAfter_;
};

}  // namespace rigmesh::model
