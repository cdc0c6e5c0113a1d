#include "model/commands/DeleteKeyCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

namespace {

ClipEdit withoutKey(const PartNode& node, double time) {
    return localClipEdit(node.clip, {time}, [&](rigmesh::Clip& clip) { clip.removeKey(time); });
}

}  // namespace

DeleteKeyCommand::DeleteKeyCommand(Document& document, PartId id, double time, QUndoCommand* parent)
    : ClipCommand(document, id, withoutKey(document.part(id), time), parent), time_(time) {
    setText(tr("Delete key of %1 at %2 s").arg(document.part(id).name).arg(time));
}

nlohmann::json DeleteKeyCommand::recipeStep() const {
    return {{"command", "delete_key"}, {"part", partIndex()}, {"time", time_}};
}

}  // namespace rigmesh::model
