#include "model/commands/SetPoseCommand.h"

#include <nlohmann/json.hpp>

#include "model/recipe/RecipeJson.h"

#include "base/Error.h"

namespace rigmesh::model {

namespace {

// `starting`: the pose the command starts from, else the one it sets.
void checkPoseFits(const PartNode& node, const rigmesh::Pose& pose, bool starting) {
    if (!pose.isFinite())
        throw Error(starting ? MessageId::StartingPoseInvalid : MessageId::NewPoseInvalid, node.id);
    for (const auto& entry : pose.rotations) {
        if (!node.part || !node.part->skeleton.hasJoint(entry.first))
            throw Error(
                starting ? MessageId::StartingPoseForeignJoint : MessageId::NewPoseForeignJoint,
                entry.first, node.id);
    }
}

}  // namespace

SetPoseCommand::SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& to,
                               rigmesh::JointId draggedJoint, CommandMerging merging,
                               QUndoCommand* parent)
    : SetPoseCommand(document, id, document.part(id).pose, to, draggedJoint, merging, parent) {}

SetPoseCommand::SetPoseCommand(Document& document, PartId id, const rigmesh::Pose& from,
                               const rigmesh::Pose& to, rigmesh::JointId draggedJoint,
                               CommandMerging merging, QUndoCommand* parent)
    : QUndoCommand(parent),
      document_(document),
      id_(id),
      index_(document.indexOf(id)),
      joint_(draggedJoint),
      from_(from),
      to_(to),
      merging_(merging) {
    const PartNode& node = document.part(id);
    if (draggedJoint != rigmesh::kNoJoint &&
        (!node.part || !node.part->skeleton.hasJoint(draggedJoint)))
        throw Error(MessageId::DocumentPartHasNoJoint, id, draggedJoint);
    checkPoseFits(node, from_, true);
    checkPoseFits(node, to_, false);
    setText(tr("Pose %1").arg(draggedJoint == rigmesh::kNoJoint ? node.name
                                                                : jointDisplayName(draggedJoint)));
    setObsolete(identicalPoses(from_, to_));
}

void SetPoseCommand::redo() {
    document_.setPose(id_, to_);
}

// The pose as it ends up (after merges), complete: joints not listed are at
// rest, so the replayed pose has exactly the same rotations.
nlohmann::json SetPoseCommand::recipeStep() const {
    nlohmann::json step = {{"command", "pose"},
                           {"part", index_},
                           {"rotations", recipe::rotationsJson(to_)},
                           {"rootTranslation", recipe::vec3Json(to_.rootTranslation)},
                           {"complete", true}};
    if (joint_ != rigmesh::kNoJoint)
        step["joint"] = joint_;
    return step;
}

void SetPoseCommand::undo() {
    document_.setPose(id_, from_);
}

bool SetPoseCommand::mergeWith(const QUndoCommand* other) {
    if (other->id() != id())
        return false;
    const auto* pose = static_cast<const SetPoseCommand*>(other);
    if (pose->id_ != id_ || pose->joint_ != joint_ || &pose->document_ != &document_)
        return false;
    to_ = pose->to_;
    setObsolete(identicalPoses(from_, to_));
    return true;
}

}  // namespace rigmesh::model
