#include "model/commands/WeightCleanupCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "part/WeightPaint.h"

namespace rigmesh::model {

WeightCleanupCommand::WeightCleanupCommand(Document& document, PartId part)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      before_(document.part(part).part) {
    if (!before_ || before_->skeleton.boneCount() == 0)
        throw Error("The part has no skeleton, so it has no weights to clean up.");
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::normalizeAll(Document& document,
                                                                         PartId part) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    auto after = std::make_shared<Part>(*command->before_);
    command->changed_ = normalizeAllWeights(*after);
    command->after_ = std::move(after);
    command->step_ = {{"command", "normalize_weights"}, {"part", command->index_}};
    command->setText(tr("Normalize All Weights of %1").arg(document.part(part).name));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::clean(Document& document, PartId part,
                                                                  double threshold) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    auto after = std::make_shared<Part>(*command->before_);
    command->changed_ = cleanWeights(*after, threshold);
    command->after_ = std::move(after);
    command->step_ = {
        {"command", "clean_weights"}, {"part", command->index_}, {"threshold", threshold}};
    command->setText(tr("Clean Weights of %1").arg(document.part(part).name));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::limitTotal(Document& document,
                                                                       PartId part,
                                                                       int influences) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    auto after = std::make_shared<Part>(*command->before_);
    command->changed_ = limitWeightInfluences(*after, influences);
    command->after_ = std::move(after);
    command->step_ = {
        {"command", "limit_weights"}, {"part", command->index_}, {"influences", influences}};
    command->setText(tr("Limit Total Weights of %1").arg(document.part(part).name));
    return command;
}

// Only the weights change: the pose, pins and keys stay.
void WeightCleanupCommand::redo() {
    const PartNode node = document_.part(id_);
    document_.replacePart(id_, after_, node.options, node.pose, node.pinnedJoints, node.clip);
}

void WeightCleanupCommand::undo() {
    const PartNode node = document_.part(id_);
    document_.replacePart(id_, before_, node.options, node.pose, node.pinnedJoints, node.clip);
}

nlohmann::json WeightCleanupCommand::recipeStep() const {
    return step_;
}

}  // namespace rigmesh::model
