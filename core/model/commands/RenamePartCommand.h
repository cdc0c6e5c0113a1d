// Rename a part.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class RenamePartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(RenamePartCommand)
  public:
    // Throws rigmesh::Error on an unknown id.
    RenamePartCommand(Document& document, PartId id, const QString& name,
                      QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    Document& document_;
    PartId id_;
    int index_;
    QString oldName_, newName_;
};

}  // namespace rigmesh::model
