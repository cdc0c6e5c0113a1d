#include "model/commands/RenamePartCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

RenamePartCommand::RenamePartCommand(Document& document, PartId id, const QString& name,
                                     QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      oldName_(document.part(id).name),
      newName_(name) {
    setText(tr("Rename %1 to %2").arg(oldName_, newName_));
}

void RenamePartCommand::redo() {
    document_.setName(id_, newName_);
}

nlohmann::json RenamePartCommand::recipeStep() const {
    return {{"command", "rename"}, {"part", index_}, {"name", newName_.toStdString()}};
}

void RenamePartCommand::undo() {
    document_.setName(id_, oldName_);
}

}  // namespace rigmesh::model
