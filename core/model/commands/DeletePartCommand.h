// Delete a part; undo puts it back at the same position with the same id.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class DeletePartCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(DeletePartCommand)
  public:
    // Throws rigmesh::Error on an unknown id.
    DeletePartCommand(Document& document, PartId id, QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    Document& document_;
    PartId id_;
    int index_;
    PartNode removed_;  // held while the part is deleted
};

}  // namespace rigmesh::model
