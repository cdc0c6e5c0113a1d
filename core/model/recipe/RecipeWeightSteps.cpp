#include "model/recipe/RecipeWeightSteps.h"

#include <cmath>
#include <sstream>

#include "model/commands/PaintWeightsCommand.h"
#include "model/commands/SetBoneLockCommand.h"
#include "model/commands/WeightCleanupCommand.h"

namespace rigmesh::model::recipe {

namespace {

BoneId boneOf(const Context& c, const PartNode& node) {
    const BoneId bone = readJointId(c.required("bone"), "\"bone\"");
    if (!node.part || !node.part->skeleton.hasBone(bone))
        throw Error(MessageId::RecipePartHasNoBone, node.name.toStdString(), bone);
    return bone;
}

// paint_weights: one dab ("center", "radius") or a stroke ("dabs").
StepCommand paintWeights(const Context& c) {
    const PartId id = c.part();
    WeightDab brush;
    brush.bone = boneOf(c, c.node(id));
    if (c.has("mode")) {
        const auto mode = brushModeNamed(readText(c.step["mode"], "\"mode\""));
        if (!mode)
            throw Error(MessageId::RecipePaintMode);
        brush.mode = *mode;
    }
    if (c.has("falloff")) {
        const auto falloff = brushFalloffNamed(readText(c.step["falloff"], "\"falloff\""));
        if (!falloff)
            throw Error(MessageId::RecipeFalloff);
        brush.falloff = *falloff;
    }
    brush.strength = c.has("strength") ? c.number("strength") : 0.5;
    if (c.has("value"))
        brush.value = c.number("value");
    brush.mirror = c.has("mirror") && readBool(c.step["mirror"], "\"mirror\"");
    if (c.has("frontFacesOnly"))
        brush.towardsViewer = readVec3(c.step["frontFacesOnly"], "\"frontFacesOnly\"");
    if (c.has("locked")) {
        if (!c.step["locked"].is_array())
            throw Error(MessageId::RecipeLockedBones);
        for (const json& bone : c.step["locked"])
            brush.locked.insert(readJointId(bone, "\"locked\""));
    }
    std::vector<WeightDab> dabs;
    // `dabOfList`: `at` is one of "dabs", else the step itself.
    auto addDab = [&](const json& at, bool dabOfList) {
        if (!at.is_object() || !at.contains("center") || !at.contains("radius"))
            throw Error(dabOfList ? MessageId::RecipeDabNeedsCenter
                                  : MessageId::RecipeStepNeedsCenter);
        WeightDab dab = brush;
        dab.centre = readVec3(at["center"], "\"center\"");
        dab.radius = readNumber(at["radius"], "\"radius\"");
        dabs.push_back(std::move(dab));
    };
    if (c.has("dabs") == (c.has("center") || c.has("radius")))
        throw Error(MessageId::RecipeDabsOrCenter);
    if (c.has("dabs")) {
        if (!c.step["dabs"].is_array() || c.step["dabs"].empty())
            throw Error(MessageId::RecipeDabsList);
        for (const json& dab : c.step["dabs"])
            addDab(dab, true);
    } else {
        addDab(c.step, false);
    }
    auto command = PaintWeightsCommand::create(c.document, id, std::move(dabs));
    std::ostringstream detail;
    detail << command->changedVertices() << " vertices changed";
    if (command->skippedVertices() > 0)
        detail << ", " << command->skippedVertices()
               << " left as they were (every other bone there is locked)";
    if (command->skippedOnlyBone() > 0)
        detail << ", " << command->skippedOnlyBone()
               << " left as they were (the part has one bone only)";
    if (command->unpairedVertices() > 0)
        detail << ", " << command->unpairedVertices()
               << " painted on one side only (no mirror partner within half an edge)";
    return {std::move(command), id, detail.str()};
}

// A whole number from `low` to `high` (checked before any cast).
int wholeNumber(const Context& c, const char* key, int low, int high) {
    const double value = c.number(key);
    if (!(value >= low && value <= high) || value != std::floor(value))
        throw Error(MessageId::RecipeWholeNumber, key, low, high);
    return static_cast<int>(value);
}

StepCommand cleanup(std::unique_ptr<WeightCleanupCommand> command, PartId id) {
    std::ostringstream detail;
    detail << command->changedVertices() << " vertices changed";
    return {std::move(command), id, detail.str()};
}

}  // namespace

StepKinds withWeightSteps(StepKinds kinds) {
    kinds.insert({
        {"paint_weights",
         {{"part", "bone", "mode", "falloff", "center", "radius", "dabs", "strength", "value",
           "mirror", "frontFacesOnly", "locked"},
          paintWeights}},
        {"normalize_weights",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return cleanup(WeightCleanupCommand::normalizeAll(c.document, id), id);
          }}},
        {"clean_weights",
         {{"part", "threshold"},
          [](const Context& c) {
              const PartId id = c.part();
              const double threshold = c.has("threshold") ? c.number("threshold") : 0.01;
              return cleanup(WeightCleanupCommand::clean(c.document, id, threshold), id);
          }}},
        {"limit_weights",
         {{"part", "influences"},
          [](const Context& c) {
              const PartId id = c.part();
              const int influences =
                  c.has("influences") ? wholeNumber(c, "influences", 1, 1000) : 4;
              return cleanup(WeightCleanupCommand::limitTotal(c.document, id, influences), id);
          }}},
        {"smooth_weights",
         {{"part", "factor", "iterations"},
          [](const Context& c) {
              const PartId id = c.part();
              SmoothAllOptions options;
              if (c.has("factor"))
                  options.factor = c.number("factor");
              if (c.has("iterations"))
                  options.iterations = wholeNumber(c, "iterations", 1, 100);
              return cleanup(WeightCleanupCommand::smoothAll(c.document, id, options), id);
          }}},
        {"recompute_weights",
         {{"part"},
          [](const Context& c) {
              const PartId id = c.part();
              return cleanup(WeightCleanupCommand::recompute(c.document, id), id);
          }}},
        {"lock_bone",
         {{"part", "bone"},
          [](const Context& c) {
              const PartId id = c.part();
              return StepCommand{
                  SetBoneLockCommand::create(c.document, id, boneOf(c, c.node(id)), true), id, {}};
          }}},
        {"unlock_bone",
         {{"part", "bone"},
          [](const Context& c) {
              const PartId id = c.part();
              return StepCommand{
                  SetBoneLockCommand::create(c.document, id, boneOf(c, c.node(id)), false), id, {}};
          }}},
    });
    return kinds;
}

}  // namespace rigmesh::model::recipe
