#include "model/commands/DeletePartCommand.h"

#include <nlohmann/json.hpp>

#include "model/recipe/RecipeJson.h"

namespace rigmesh::model {

DeletePartCommand::DeletePartCommand(Document& document, PartId id, QUndoCommand* parent)
    : QUndoCommand(parent), document_(document), id_(id), index_(document.indexOf(id)) {
    setText(tr("Delete %1").arg(document.part(id).name));
}

void DeletePartCommand::redo() {
    index_ = document_.indexOf(id_);
    removed_ = document_.removePart(id_);
}

nlohmann::json DeletePartCommand::recipeStep() const {
    return {{"command", "delete"}, {"part", index_}};
}

void DeletePartCommand::undo() {
    document_.insertPart(index_, std::move(removed_));
    removed_ = {};
}

}  // namespace rigmesh::model
