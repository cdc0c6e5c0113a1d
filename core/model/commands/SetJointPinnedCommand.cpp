#include "model/commands/SetJointPinnedCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh::model {

SetJointPinnedCommand::SetJointPinnedCommand(Document& document, PartId id, rigmesh::JointId joint,
                                             bool pinned, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      joint_(joint),
      pinned_(pinned),
      old_(document.part(id).pinnedJoints) {
    const PartNode& node = document.part(id);
    if (!node.part || !node.part->skeleton.hasJoint(joint))
        throw Error(MessageId::DocumentPartHasNoJoint, id, joint);
    new_ = old_;
    if (pinned)
        new_.insert(joint);
    else
        new_.erase(joint);
    const QString name = jointDisplayName(joint);
    setText(pinned ? tr("Pin %1").arg(name) : tr("Unpin %1").arg(name));
    setObsolete(old_ == new_);
}

void SetJointPinnedCommand::redo() {
    document_.setPinnedJoints(id_, new_);
}

nlohmann::json SetJointPinnedCommand::recipeStep() const {
    return {{"command", pinned_ ? "pin" : "unpin"}, {"part", index_}, {"joint", joint_}};
}

void SetJointPinnedCommand::undo() {
    document_.setPinnedJoints(id_, old_);
}

}  // namespace rigmesh::model
