#include "model/recipe/RecipeFromHistory.h"

#include <QUndoCommand>
#include <QUndoStack>

#include "base/Error.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeStepSource.h"

namespace rigmesh::model {

namespace {

// A macro (a command with children and no step of its own) gives its
// children's steps in order.
void appendSteps(const QUndoCommand& command, nlohmann::json& steps) {
    if (const auto* source = dynamic_cast<const RecipeStepSource*>(&command)) {
        steps.push_back(source->recipeStep());
        return;
    }
    if (command.childCount() == 0)
        throw Error(MessageId::HistoryStepNotRecipe, command.text().toStdString());
    for (int i = 0; i < command.childCount(); ++i)
        appendSteps(*command.child(i), steps);
}

}  // namespace

nlohmann::json recipeFromHistory(const Document& document) {
    nlohmann::json recipe = emptyRecipe();
    nlohmann::json& steps = recipe["steps"];
    const QUndoStack& stack = *document.undoStack();
    for (int i = 0; i < stack.index(); ++i)
        appendSteps(*stack.command(i), steps);
    return recipe;
}

void saveHistoryAsRecipe(const Document& document, const std::string& path) {
    writeRecipeFile(recipeFromHistory(document), path);
}

}  // namespace rigmesh::model
