// What every recipe step kind is made of (RecipeStepCommands.cpp and the
// step families beside it, such as RecipeWeightSteps.cpp): the fields a step
// may have and how it builds its command, with the step's context. Internal
// to core/model/recipe.
#pragma once

#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "base/Error.h"
#include "model/Document.h"
#include "model/recipe/RecipeJson.h"
#include "model/recipe/RecipePartRef.h"
#include "model/recipe/RecipeStepCommands.h"

namespace rigmesh::model::recipe {

using nlohmann::json;

struct Context {
    Document& document;
    const json& step;
    const std::filesystem::path& baseDirectory;
    const StepOptions& options;

    bool has(const char* key) const { return step.contains(key); }
    const json& required(const char* key) const {
        if (!step.contains(key))
            throw Error(MessageId::RecipeStepNeeds, key);
        return step[key];
    }
    PartId part() const { return resolvePart(document, required("part")); }
    const PartNode& node(PartId id) const { return document.part(id); }
    double number(const char* key) const {
        return readNumber(required(key), std::string("\"") + key + "\"");
    }
    // A joint of the part, by the step's "joint".
    JointId joint(const PartNode& node) const {
        const JointId joint = readJointId(required("joint"), "\"joint\"");
        checkJoint(node, joint);
        return joint;
    }
    static void checkJoint(const PartNode& node, JointId joint) {
        if (!node.part || !node.part->skeleton.hasJoint(joint))
            throw Error(MessageId::RecipePartHasNoJoint, node.name.toStdString(), joint);
    }
};

using Builder = std::function<StepCommand(const Context&)>;

struct StepKind {
    std::set<std::string> fields;  // besides "command" and "comment"
    Builder build;
};

template <typename Command, typename... Args>
StepCommand make(PartId part, Args&&... args) {
    return {std::make_unique<Command>(std::forward<Args>(args)...), part, {}};
}

using StepKinds = std::map<std::string, StepKind>;

}  // namespace rigmesh::model::recipe
