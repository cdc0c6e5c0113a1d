// Show or hide a part.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class SetPartVisibleCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(SetPartVisibleCommand)
  public:
    // Throws rigmesh::Error on an unknown id.
    SetPartVisibleCommand(Document& document, PartId id, bool visible,
                          QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    Document& document_;
    PartId id_;
    int index_;
    bool old_, new_;
};

}  // namespace rigmesh::model
