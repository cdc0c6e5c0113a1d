#include "model/commands/WeightCleanupCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"

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

WeightCleanupCommand::Recomputed WeightCleanupCommand::recomputed(
    std::shared_ptr<const Part> part) {
    if (!part)
        throw Error(MessageId::RecomputeNoPart);
    auto after = std::make_shared<Part>(*part);
    Recomputed result;
    result.changed = recomputeWeights(*after, after->lockedBones);
    after->weightsPainted = false;
    result.from = std::move(part);
    result.to = std::move(after);
    return result;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::fromRecomputed(
    Document& document, PartId part, const Recomputed& result) {
    if (!document.contains(part))
        throw Error(MessageId::PartGone);
    std::unique_ptr<WeightCleanupCommand> command(new WeightCleanupCommand(document, part));
    if (&command->before() != result.from.get())
        throw Error(MessageId::RecomputePartChanged);
    command->setResult(result.to,
                       {{"command", "recompute_weights"}, {"part", command->partIndex()}},
                       result.changed);
    command->setText(tr("Recompute Weights of %1").arg(command->partName()));
    return command;
}

std::unique_ptr<WeightCleanupCommand> WeightCleanupCommand::recompute(Document& document,
                                                                      PartId part) {
    if (!document.contains(part))
        throw Error(MessageId::NoSuchPart);
    return fromRecomputed(document, part, recomputed(document.part(part).part));
}

}  // namespace rigmesh::model
