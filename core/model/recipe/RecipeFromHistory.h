// A document's undo history as a recipe: the steps of the commands up to the
// stack's current index (undone commands are left out; a merged drag is one
// "pose" step with its final rotations). Replayed by a RecipeRunner on a new
// document, the recipe makes the same document, bit for bit, when the
// history starts from an empty document (a new one, not a loaded file).
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/Document.h"

namespace rigmesh::model {

// Throws rigmesh::Error on a command that cannot be written as a step (one
// that is not a RecipeStepSource and has no child commands).
nlohmann::json recipeFromHistory(const Document& document);

// recipeFromHistory() then writeRecipeFile(). Throws rigmesh::Error.
void saveHistoryAsRecipe(const Document& document, const std::string& path);

}  // namespace rigmesh::model
