#include "model/commands/KeyPoseCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

namespace {

ClipEdit keyed(const PartNode& node, double time) {
    return localClipEdit(node.clip, {time},
                         [&](rigmesh::Clip& clip) { clip.setKey(time, node.pose); });
}

}  // namespace

KeyPoseCommand::KeyPoseCommand(Document& document, PartId id, double time, QUndoCommand* parent)
    : ClipCommand(document, id, keyed(document.part(id), time), parent), time_(time) {
    setText(tr("Key %1 at %2 s").arg(document.part(id).name).arg(time));
}

nlohmann::json KeyPoseCommand::recipeStep() const {
    return {{"command", "key"}, {"part", partIndex()}, {"time", time_}};
}

}  // namespace rigmesh::model
