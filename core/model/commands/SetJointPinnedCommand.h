// Pin or unpin one joint of a part (pinned joints stay in place under IK).
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <set>

#include "model/Document.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

class SetJointPinnedCommand : public QUndoCommand, public RecipeStepSource {
    Q_DECLARE_TR_FUNCTIONS(SetJointPinnedCommand)
  public:
    // Throws rigmesh::Error on an unknown part or joint. Obsolete (dropped on
    // push) when the joint already is in that state.
    SetJointPinnedCommand(Document& document, PartId id, rigmesh::JointId joint, bool pinned,
                          QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;
    nlohmann::json recipeStep() const override;

  private:
    Document& document_;
    PartId id_;
    int index_;
    rigmesh::JointId joint_;
    bool pinned_;
    std::set<rigmesh::JointId> old_, new_;
};

}  // namespace rigmesh::model
