// `rigmesh run RECIPE.json [-o OUT]`: replays a recipe (see
// core/model/recipe/RecipeRunner.h) on a new document with the model's
// runner, printing one line per step, and writes the document.
#pragma once

#include <string>
#include <vector>

namespace rigmesh::cli {

// Runs the run command; returns the process exit code. Throws rigmesh::Error
// with a one-line reason on bad input; a bad step throws
// rigmesh::model::RecipeError ("step N (command): reason").
int runRecipe(const std::vector<std::string>& arguments);

}  // namespace rigmesh::cli
