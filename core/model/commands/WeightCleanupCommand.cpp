#include "model/commands/WeightCleanupCommand.h"

#include <nlohmann/json.hpp>

namespace rigmesh::model {

template <typename Edit>
void WeightCleanupCommand::apply(Edit&& edit, nlohmann::json step, const QString& text) {
    auto after = editableCopy();
    const int changed = edit(*after);
    if (changed > 0)
        after->weightsPainted = true;
    setResult(std::move(after), std::move(step), changed);
    setText(text.arg(partName()));
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::normalizeAll(Document& document,
                                                                         PartId part) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    command->apply([](Part& p) { return normalizeAllWeights(p, p.lockedBones); },
                   {{"command", "normalize_weights"}, {"part", command->partIndex()}},
                   tr("Normalize All Weights of %1"));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::clean(Document& document, PartId part,
                                                                  double threshold) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    command->apply(
        [&](Part& p) { return cleanWeights(p, threshold, p.lockedBones); },
        {{"command", "clean_weights"}, {"part", command->partIndex()}, {"threshold", threshold}},
        tr("Clean Weights of %1"));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::limitTotal(Document& document,
                                                                       PartId part,
                                                                       int influences) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    command->apply(
        [&](Part& p) { return limitWeightInfluences(p, influences, p.lockedBones); },
        {{"command", "limit_weights"}, {"part", command->partIndex()}, {"influences", influences}},
        tr("Limit Total Weights of %1"));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::smoothAll(
    Document& document, PartId part, const SmoothAllOptions& options) {
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    command->apply([&](Part& p) { return smoothAllWeights(p, options, p.lockedBones); },
                   {{"command", "smooth_weights"},
                    {"part", command->partIndex()},
                    {"factor", options.factor},
                    {"iterations", options.iterations}},
                   tr("Smooth All Weights of %1"));
    return command;
}

}  // namespace rigmesh::model
