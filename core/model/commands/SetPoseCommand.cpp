#include "model/commands/SetPoseCommand.h"

#include <nlohmann/json.hpp>

#include "model/recipe/RecipeJson.h"

#include "base/Error.h"

namespace rigmesh::model {

namespace {

void checkPoseFits(const PartNode& node, const rigmesh::Pose& pose, const char* what) {
    if (!pose.isFinite())
        throw Error(std::string("The ") + what + " pose of part " + std::to_string(node.id) +
                    " has a non-finite or zero rotation or translation.");
    for (const auto& entry : pose.rotations) {
        if (!node.part || !node.part->skeleton.hasJoint(entry.first))
            throw Error(std::string("The ") + what + " pose names joint " +
                        std::to_string(entry.first) + ", which part " + std::to_string(node.id) +
                        " does not have.");
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
        throw Error("Part " + std::to_string(id) + " has no joint " + std::to_string(draggedJoint) +
                    ".");
    checkPoseFits(node, from_, "starting");
    checkPoseFits(node, to_, "new");
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
