#include "model/commands/ResetPoseCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

ResetPoseCommand::ResetPoseCommand(Document& document, PartId id, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      from_(document.part(id).pose),
      to_(restPoseOf(document.part(id))) {
    setText(tr("Reset pose of %1").arg(document.part(id).name));
    setObsolete(identicalPoses(from_, to_));
}

void ResetPoseCommand::redo() {
    document_.setPose(id_, to_);
}

nlohmann::json ResetPoseCommand::recipeStep() const {
    return {{"command", "reset_pose"}, {"part", index_}};
}

void ResetPoseCommand::undo() {
    document_.setPose(id_, from_);
}

}  // namespace rigmesh::model
