#include "model/recipe/RecipeError.h"

#include <utility>

namespace rigmesh::model {

RecipeError::RecipeError(int step, std::string command, Message reason)
    : rigmesh::Error(Message{
          MessageId::RecipeStepFailed, {std::to_string(step), command}, {std::move(reason)}}),
      step_(step),
      command_(std::move(command)) {}

}  // namespace rigmesh::model
