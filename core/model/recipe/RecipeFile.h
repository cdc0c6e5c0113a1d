// Recipe files: JSON text, {"format": "rigmesh-recipe", "version": 3,
// "steps": [...]} (see RecipeRunner.h for the steps). Version 2 (per-bone
// pose rotations) reads version 1 recipes too; version 3 mirrors the joints
// of symmetric sketches, which older recipes replay without.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "model/Document.h"
#include "model/recipe/RecipeRunner.h"
#include "model/recipe/RecipeStepCommands.h"

namespace rigmesh::model {

namespace RecipeFile {
inline constexpr const char* kFormatName = "rigmesh-recipe";
inline constexpr int kFormatVersion = 3;
static_assert(recipe::StepOptions{}.formatVersion == kFormatVersion,
              "steps run as the current version by default");
}  // namespace RecipeFile

// An empty recipe: the header and no steps.
nlohmann::json emptyRecipe();
// The recipe's list of steps after checking its format and version. Throws
// rigmesh::Error ("this is not a RigMesh recipe", a newer version, ...).
const nlohmann::json& recipeSteps(const nlohmann::json& recipe);

// Parses recipe text; `sourceName` names it in messages. Throws rigmesh::Error.
nlohmann::json parseRecipe(const std::string& text, const std::string& sourceName);
// Reads and parses a file. Throws rigmesh::Error.
nlohmann::json readRecipeFile(const std::string& path);
// Writes the recipe as indented JSON (doubles in round-trip precision).
// Throws rigmesh::Error.
void writeRecipeFile(const nlohmann::json& recipe, const std::string& path);

// Runs a recipe file on `document`, stroke files relative to the file's
// folder. Throws rigmesh::Error for an unreadable or malformed file and
// RecipeError for a bad step.
void runRecipeFile(Document& document, const std::string& path,
                   const RecipeRunner::StepCallback& onStep = {},
                   const recipe::StepOptions& options = {});

}  // namespace rigmesh::model
