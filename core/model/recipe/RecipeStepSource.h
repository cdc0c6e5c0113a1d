// What every document command implements: itself as one recipe step (see
// RecipeRunner.h for the format). Replayed by a RecipeRunner on the document
// as it was just before the command, the step does what the command did,
// bit for bit; recipeFromHistory() strings the steps of an undo stack
// together.
#pragma once

#include <nlohmann/json_fwd.hpp>

namespace rigmesh::model {

class RecipeStepSource {
  public:
    virtual ~RecipeStepSource() = default;
    // One step object, {"command": "...", ...}; parts are referred to by
    // their index in the document when the command was made.
    virtual nlohmann::json recipeStep() const = 0;

  protected:
    RecipeStepSource() = default;
    RecipeStepSource(const RecipeStepSource&) = default;
    RecipeStepSource& operator=(const RecipeStepSource&) = default;
};

}  // namespace rigmesh::model
