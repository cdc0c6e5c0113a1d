#include "model/commands/RebuildPartCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/recipe/RecipeJson.h"

#include "model/PartBuilder.h"
#include "model/RigCarryOver.h"

namespace rigmesh::model {

std::unique_ptr<RebuildPartCommand> RebuildPartCommand::create(Document& document, PartId id,
                                                               const BuildOptions& options) {
    const PartNode& node = document.part(id);
    // Merges, cuts, bone edits and imports leave a part without a stroke.
    if (node.stroke.empty())
        throw Error(MessageId::PartHasNoSketch, node.name.toStdString());
    return fromBuilt(document, id, buildPart(node.stroke, node.name, options), options);
}

std::unique_ptr<RebuildPartCommand> RebuildPartCommand::fromBuilt(Document& document, PartId id,
                                                                  std::shared_ptr<const Part> part,
                                                                  const BuildOptions& options) {
    document.part(id);  // throws on an unknown id
    return std::unique_ptr<RebuildPartCommand>(
        new RebuildPartCommand(document, id, std::move(part), options));
}

RebuildPartCommand::RebuildPartCommand(Document& document, PartId id,
                                       std::shared_ptr<const Part> part,
                                       const BuildOptions& options)
    : document_(document),
      id_(id),
      index_(document.indexOf(id)),
      oldPart_(document.part(id).part),
      newPart_(std::move(part)),
      oldOptions_(document.part(id).options),
      newOptions_(options),
      oldPose_(document.part(id).pose),
      oldPinned_(document.part(id).pinnedJoints),
      oldClip_(document.part(id).clip),
      oldOtherClips_(document.part(id).otherClips) {
    // Pose, pins and keys carry over where the new skeleton keeps the joints.
    const CarriedRig carried = carryRigOver(oldPart_->skeleton, newPart_->skeleton, oldPose_,
                                            oldPinned_, oldClip_, oldOtherClips_);
    newPose_ = carried.pose;
    newPinned_ = carried.pinned;
    newClip_ = carried.clip;
    newOtherClips_ = carried.otherClips;
    droppedJoints_ = carried.droppedJoints;
    setText(tr("Rebuild %1").arg(document.part(id).name));
}

QString RebuildPartCommand::droppedMessage() const {
    if (droppedJoints_ == 0)
        return {};
    return tr(
        "the pose, pins and keys of %n joint(s) were dropped: the new skeleton has no "
        "joint there",
        nullptr, droppedJoints_);
}

void RebuildPartCommand::redo() {
    document_.replacePart(id_, newPart_, newOptions_, newPose_, newPinned_, newClip_,
                          newOtherClips_);
}

nlohmann::json RebuildPartCommand::recipeStep() const {
    return {
        {"command", "rebuild"}, {"part", index_}, {"options", recipe::optionsJson(newOptions_)}};
}

void RebuildPartCommand::undo() {
    document_.replacePart(id_, oldPart_, oldOptions_, oldPose_, oldPinned_, oldClip_,
                          oldOtherClips_);
}

}  // namespace rigmesh::model
