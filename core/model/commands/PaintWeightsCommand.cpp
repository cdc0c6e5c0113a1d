#include "model/commands/PaintWeightsCommand.h"

#include <nlohmann/json.hpp>

#include "base/Error.h"

namespace rigmesh::model {

namespace {

const char* modeName(BrushMode mode) {
    switch (mode) {
        case BrushMode::Add:
            return "add";
        case BrushMode::Subtract:
            return "subtract";
        case BrushMode::Replace:
            return "replace";
        case BrushMode::Smooth:
            return "smooth";
    }
    return "add";
}

}  // namespace

std::unique_ptr<PaintWeightsCommand> PaintWeightsCommand::create(Document& document, PartId part,
                                                                 const WeightDab& dab) {
    return std::unique_ptr<PaintWeightsCommand>(new PaintWeightsCommand(document, part, dab));
}

PaintWeightsCommand::PaintWeightsCommand(Document& document, PartId part, const WeightDab& dab)
    : document_(document),
      id_(part),
      index_(document.indexOf(part)),
      dab_(dab),
      before_(document.part(part).part) {
    if (!before_ || before_->skeleton.boneCount() == 0)
        throw Error("The part has no skeleton, so it has no weights to paint.");
    const Placement& placement = document.part(part).placement;
    WeightDab local = dab;
    local.centre = placement.rotation.conjugate() * (dab.centre - placement.translation);
    auto painted = std::make_shared<Part>(*before_);
    const DabResult result = paintWeights(*painted, local);
    changed_ = static_cast<int>(result.changed.size());
    skipped_ = result.skippedLocked;
    after_ = std::move(painted);
    setText(tr("Paint Weights of %1").arg(document.part(part).name));
}

// Only the weights change: the skeleton, and with it the pose, pins and
// keys, stay as they are.
void PaintWeightsCommand::redo() {
    const PartNode node = document_.part(id_);  // a copy: replacePart changes the node
    document_.replacePart(id_, after_, node.options, node.pose, node.pinnedJoints, node.clip);
}

void PaintWeightsCommand::undo() {
    const PartNode node = document_.part(id_);
    document_.replacePart(id_, before_, node.options, node.pose, node.pinnedJoints, node.clip);
}

nlohmann::json PaintWeightsCommand::recipeStep() const {
    nlohmann::json step = {{"command", "paint_weights"},
                           {"part", index_},
                           {"bone", dab_.bone},
                           {"mode", modeName(dab_.mode)},
                           {"center", {dab_.centre.x(), dab_.centre.y(), dab_.centre.z()}},
                           {"radius", dab_.radius},
                           {"strength", dab_.strength},
                           {"mirror", dab_.mirror}};
    if (dab_.mode == BrushMode::Replace)
        step["value"] = dab_.value;
    if (!dab_.locked.empty())
        step["locked"] = std::vector<BoneId>(dab_.locked.begin(), dab_.locked.end());
    return step;
}

}  // namespace rigmesh::model
