// Recipe steps that edit skin weights: paint_weights,
// normalize_weights, clean_weights, limit_weights, smooth_weights,
// recompute_weights,
// lock_bone and unlock_bone (formats in RecipeRunner.h).
#pragma once

#include "model/recipe/RecipeStepKind.h"

namespace rigmesh::model::recipe {

// `kinds` with the weight steps added.
StepKinds withWeightSteps(StepKinds kinds);

}  // namespace rigmesh::model::recipe
