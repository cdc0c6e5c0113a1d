#include "model/commands/MovePartCommand.h"

#include <nlohmann/json.hpp>

#include "model/recipe/RecipeJson.h"

namespace rigmesh::model {

MovePartCommand::MovePartCommand(Document& document, PartId id, const Placement& from,
                                 const Placement& to, CommandMerging merging, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      from_(from),
      to_(to),
      merging_(merging) {
    const PartNode& node = document.part(id);
    setText(from.rotation.coeffs() == to.rotation.coeffs() ? tr("Move %1").arg(node.name)
                                                           : tr("Rotate %1").arg(node.name));
    setObsolete(from == to);
}

MovePartCommand::MovePartCommand(Document& document, PartId id, const Placement& to,
                                 QUndoCommand* parent)
    : MovePartCommand(document, id, document.part(id).placement, to, CommandMerging::Consecutive,
                      parent) {}

void MovePartCommand::redo() {
    document_.setPlacement(id_, to_);
}

nlohmann::json MovePartCommand::recipeStep() const {
    return {{"command", "move"}, {"part", index_}, {"placement", recipe::placementJson(to_)}};
}

void MovePartCommand::undo() {
    document_.setPlacement(id_, from_);
}

bool MovePartCommand::mergeWith(const QUndoCommand* other) {
    if (other->id() != id())
        return false;
    const auto* move = static_cast<const MovePartCommand*>(other);
    if (move->id_ != id_ || &move->document_ != &document_)
        return false;
    to_ = move->to_;
    if (from_.rotation.coeffs() != to_.rotation.coeffs())
        setText(tr("Rotate %1").arg(document_.part(id_).name));
    setObsolete(from_ == to_);
    return true;
}

}  // namespace rigmesh::model
