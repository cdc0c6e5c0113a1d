#include "model/recipe/RecipeError.h"

#include <utility>

namespace rigmesh::model {

RecipeError::RecipeError(int step, std::string command, std::string reason)
    : rigmesh::Error("step " + std::to_string(step) + " (" + command + "): " + reason),
      step_(step),
      command_(std::move(command)),
      reason_(std::move(reason)) {}

}  // namespace rigmesh::model
