// Helpers of the recipe tests: recipes from step lists, running them and
// catching the step error.
#pragma once

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "model/Document.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeRunner.h"

namespace rigmesh::model::test {

inline nlohmann::json recipeWith(const std::vector<nlohmann::json>& steps) {
    nlohmann::json recipe = emptyRecipe();
    for (const nlohmann::json& step : steps)
        recipe["steps"].push_back(step);
    return recipe;
}

inline void runSteps(Document& document, const std::vector<nlohmann::json>& steps) {
    RecipeRunner(document).run(recipeWith(steps));
}

// The message of the RecipeError the steps throw ("" and a failure if none).
inline std::string stepError(Document& document, const std::vector<nlohmann::json>& steps) {
    try {
        runSteps(document, steps);
    } catch (const RecipeError& error) {
        return error.what();
    }
    ADD_FAILURE() << "the recipe ran without an error";
    return {};
}

inline nlohmann::json pointsOf(const std::vector<Vec2>& stroke) {
    nlohmann::json points = nlohmann::json::array();
    for (const Vec2& p : stroke)
        points.push_back({p.x(), p.y()});
    return points;
}

}  // namespace rigmesh::model::test
