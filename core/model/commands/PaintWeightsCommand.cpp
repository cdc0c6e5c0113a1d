#include "model/commands/PaintWeightsCommand.h"

#include <algorithm>
#include <array>
#include <nlohmann/json.hpp>
#include <stdexcept>

namespace rigmesh::model {

namespace {

constexpr std::array<std::pair<BrushMode, const char*>, 4> kModes{
    {{BrushMode::Add, "add"},
     {BrushMode::Subtract, "subtract"},
     {BrushMode::Replace, "replace"},
     {BrushMode::Smooth, "smooth"}}};
constexpr std::array<std::pair<BrushFalloff, const char*>, 4> kFalloffs{
    {{BrushFalloff::Smooth, "smooth"},
     {BrushFalloff::Linear, "linear"},
     {BrushFalloff::Sharp, "sharp"},
     {BrushFalloff::Constant, "constant"}}};

// Everything but the centre and the radius.
bool sameBrush(const WeightDab& a, const WeightDab& b) {
    const bool sameView = a.towardsViewer.has_value() == b.towardsViewer.has_value() &&
                          (!a.towardsViewer || *a.towardsViewer == *b.towardsViewer);
    return a.bone == b.bone && a.mode == b.mode && a.falloff == b.falloff &&
           a.strength == b.strength && a.value == b.value && a.mirror == b.mirror &&
           a.locked == b.locked && sameView;
}

nlohmann::json vec3(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

}  // namespace

const char* brushModeName(BrushMode mode) {
    for (const auto& [m, name] : kModes)
        if (m == mode)
            return name;
    return "add";
}

const char* brushFalloffName(BrushFalloff falloff) {
    for (const auto& [f, name] : kFalloffs)
        if (f == falloff)
            return name;
    return "smooth";
}

std::optional<BrushMode> brushModeNamed(const std::string& name) {
    for (const auto& [m, n] : kModes)
        if (name == n)
            return m;
    return std::nullopt;
}

std::optional<BrushFalloff> brushFalloffNamed(const std::string& name) {
    for (const auto& [f, n] : kFalloffs)
        if (name == n)
            return f;
    return std::nullopt;
}

std::unique_ptr<PaintWeightsCommand> PaintWeightsCommand::create(Document& document, PartId part,
                                                                 std::vector<WeightDab> dabs) {
    if (dabs.empty())
        throw std::logic_error("A paint stroke needs at least one dab.");
    if (!std::all_of(dabs.begin(), dabs.end(),
                     [&](const WeightDab& d) { return sameBrush(d, dabs.front()); }))
        throw std::logic_error("The dabs of one stroke must share bone, brush and options.");
    std::unique_ptr<PaintWeightsCommand> command(new PaintWeightsCommand(document, part));
    const Placement& placement = document.part(part).placement;
    auto painted = command->editableCopy();
    WeightPainter painter(painted->mesh);
    std::vector<int> changed;
    for (const WeightDab& dab : dabs) {
        // To the part's own coordinates, where its vertices are.
        WeightDab local = dab;
        local.centre = placement.toLocal(dab.centre);
        if (dab.towardsViewer)
            local.towardsViewer = placement.directionToLocal(*dab.towardsViewer);
        local.locked.insert(painted->lockedBones.begin(), painted->lockedBones.end());
        const DabResult result = painter.paint(*painted, local);
        changed.insert(changed.end(), result.changed.begin(), result.changed.end());
        command->skipped_ += result.skippedLocked;
        command->skippedOnlyBone_ += result.skippedOnlyBone;
        command->unpaired_ += result.unpaired;
    }
    std::sort(changed.begin(), changed.end());
    changed.erase(std::unique(changed.begin(), changed.end()), changed.end());
    if (!changed.empty())
        painted->weightsPainted = true;
    command->setResult(std::move(painted), command->step(dabs), static_cast<int>(changed.size()));
    command->setText(tr("Paint Weights of %1").arg(command->partName()));
    return command;
}

nlohmann::json PaintWeightsCommand::step(const std::vector<WeightDab>& dabs) const {
    const WeightDab& brush = dabs.front();
    nlohmann::json step = {{"command", "paint_weights"}, {"part", partIndex()},
                           {"bone", brush.bone},         {"mode", brushModeName(brush.mode)},
                           {"strength", brush.strength}, {"mirror", brush.mirror}};
    if (dabs.size() == 1) {
        step["center"] = vec3(brush.centre);
        step["radius"] = brush.radius;
    } else {
        for (const WeightDab& dab : dabs)
            step["dabs"].push_back({{"center", vec3(dab.centre)}, {"radius", dab.radius}});
    }
    if (brush.mode == BrushMode::Replace)
        step["value"] = brush.value;
    if (brush.falloff != BrushFalloff::Smooth)
        step["falloff"] = brushFalloffName(brush.falloff);
    if (brush.towardsViewer)
        step["frontFacesOnly"] = vec3(*brush.towardsViewer);
    if (!brush.locked.empty())
        step["locked"] = std::vector<BoneId>(brush.locked.begin(), brush.locked.end());
    return step;
}

}  // namespace rigmesh::model
