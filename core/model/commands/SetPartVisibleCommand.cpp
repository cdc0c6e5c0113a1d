#include "model/commands/SetPartVisibleCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

SetPartVisibleCommand::SetPartVisibleCommand(Document& document, PartId id, bool visible,
                                             QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      old_(document.part(id).visible),
      new_(visible) {
    const QString& name = document.part(id).name;
    setText(visible ? tr("Show %1").arg(name) : tr("Hide %1").arg(name));
}

void SetPartVisibleCommand::redo() {
    document_.setVisible(id_, new_);
}

nlohmann::json SetPartVisibleCommand::recipeStep() const {
    return {{"command", new_ ? "show" : "hide"}, {"part", index_}};
}

void SetPartVisibleCommand::undo() {
    document_.setVisible(id_, old_);
}

}  // namespace rigmesh::model
