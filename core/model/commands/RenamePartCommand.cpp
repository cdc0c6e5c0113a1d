#include "model/commands/RenamePartCommand.h"

namespace rigmesh::model {

RenamePartCommand::RenamePartCommand(Document& document, PartId id, const QString& name,
                                     QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      oldName_(document.part(id).name),
      newName_(name) {
    setText(tr("Rename %1 to %2").arg(oldName_, newName_));
}

void RenamePartCommand::redo() {
    document_.setName(id_, newName_);
}

void RenamePartCommand::undo() {
    document_.setName(id_, oldName_);
}

}  // namespace rigmesh::model
