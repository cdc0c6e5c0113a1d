#include "model/commands/CreatePartCommand.h"

#include <nlohmann/json.hpp>

#include "model/recipe/RecipeJson.h"

#include "model/PartBuilder.h"

namespace rigmesh::model {

std::unique_ptr<CreatePartCommand> CreatePartCommand::create(Document& document,
                                                             std::vector<Vec2> stroke,
                                                             const QString& name,
                                                             const BuildOptions& options,
                                                             const Placement& placement) {
    // Build first: a bad stroke throws here, before an id is taken.
    const QString named = name.isEmpty() ? tr("Part %1").arg(document.nextPartId()) : name;
    BuiltPart built = buildPartForDocument(document, stroke, named, options);
    return fromBuilt(document, std::move(stroke), named, std::move(built), placement);
}

std::unique_ptr<CreatePartCommand> CreatePartCommand::fromBuilt(Document& document,
                                                                std::vector<Vec2> stroke,
                                                                const QString& name,
                                                                BuiltPart built,
                                                                const Placement& placement) {
    PartNode node = nodeFromBuilt(name.isEmpty() ? tr("Part %1").arg(document.nextPartId()) : name,
                                  std::move(stroke), std::move(built), placement);
    node.id = document.allocatePartId();
    return std::unique_ptr<CreatePartCommand>(new CreatePartCommand(document, std::move(node)));
}

PartNode CreatePartCommand::nodeFromBuilt(const QString& name, std::vector<Vec2> stroke,
                                          BuiltPart built, const Placement& placement) {
    PartNode node;
    node.name = name;
    node.part = std::move(built.part);
    node.stroke = std::move(stroke);
    node.options = built.options;
    node.placement = placement;
    node.pose = restPoseOf(node);
    return node;
}

CreatePartCommand::CreatePartCommand(Document& document, PartNode node)
    : document_(document), node_(std::move(node)) {
    setText(tr("Create %1").arg(node_.name));
}

void CreatePartCommand::redo() {
    document_.insertPart(document_.partCount(), node_);
}

nlohmann::json CreatePartCommand::recipeStep() const {
    return {{"command", "sketch"},
            {"name", node_.name.toStdString()},
            {"points", recipe::pointsJson(node_.stroke)},
            {"placement", recipe::placementJson(node_.placement)},
            {"options", recipe::optionsJson(node_.options)}};
}

void CreatePartCommand::undo() {
    document_.removePart(node_.id);
    document_.releasePartId(node_.id);
}

}  // namespace rigmesh::model
