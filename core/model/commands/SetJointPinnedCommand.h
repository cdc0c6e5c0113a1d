// Pin or unpin one joint of a part (pinned joints stay in place under IK).
#pragma once

#include <QCoreApplication>
#include <QUndoCommand>
#include <set>

#include "model/Document.h"

namespace rigmesh::model {

class SetJointPinnedCommand : public QUndoCommand {
    Q_DECLARE_TR_FUNCTIONS(SetJointPinnedCommand)
  public:
    // Throws rigmesh::Error on an unknown part or joint. Obsolete (dropped on
    // push) when the joint already is in that state.
    SetJointPinnedCommand(Document& document, PartId id, rigmesh::JointId joint, bool pinned,
                          QUndoCommand* parent = nullptr);

    void redo() override;
    void undo() override;

  private:
    Document& document_;
    PartId id_;
    std::set<rigmesh::JointId> old_, new_;
};

}  // namespace rigmesh::model
