#include "model/commands/MoveKeyCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

namespace {

ClipEdit withKeyMoved(const PartNode& node, double from, double to) {
    return localClipEdit(node.clip, {from, to},
                         [&](rigmesh::Clip& clip) { clip.moveKey(from, to); });
}

}  // namespace

MoveKeyCommand::MoveKeyCommand(Document& document, PartId id, double from, double to,
                               QUndoCommand* parent)
    : ClipCommand(document, id, withKeyMoved(document.part(id), from, to), parent),
      from_(from),
      to_(to) {
    setText(tr("Move key of %1 from %2 s to %3 s").arg(document.part(id).name).arg(from).arg(to));
}

nlohmann::json MoveKeyCommand::recipeStep() const {
    return {{"command", "move_key"}, {"part", partIndex()}, {"from", from_}, {"to", to_}};
}

}  // namespace rigmesh::model
