// Put a part back in its rest pose (restPoseOf), as one undoable step. Pins
// are kept.
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class ResetPoseCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(ResetPoseCommand)
  public:
    // Throws rigmesh::Error on an unknown id. Obsolete (dropped on push) when
    // the part already is exactly in its rest pose.
    ResetPoseCommand(Document& document, PartId id, QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    Document& document_;
    PartId id_;
    int index_;
    rigmesh::Pose from_, to_;
};

}  // namespace rigmesh::model
