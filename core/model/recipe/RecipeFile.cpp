#include "model/recipe/RecipeFile.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "base/Error.h"
#include "base/JsonRead.h"

namespace rigmesh::model {

nlohmann::json emptyRecipe() {
    return {{"format", RecipeFile::kFormatName},
            {"version", RecipeFile::kFormatVersion},
            {"steps", nlohmann::json::array()}};
}

const nlohmann::json& recipeSteps(const nlohmann::json& recipe) {
    if (!recipe.is_object() || !recipe.contains("format") || !recipe["format"].is_string() ||
        recipe["format"].get<std::string>() != RecipeFile::kFormatName)
        throw Error(std::string("this is not a RigMesh recipe (it needs \"format\": \"") +
                    RecipeFile::kFormatName + "\")");
    const auto version = recipe.find("version");
    if (version == recipe.end() || !version->is_number_integer() ||
        version->get<std::int64_t>() < 1)
        throw Error("the recipe has no valid \"version\"");
    if (version->get<std::int64_t>() > RecipeFile::kFormatVersion)
        throw Error("the recipe is of version " + std::to_string(version->get<std::int64_t>()) +
                    "; this RigMesh Studio reads recipes of version " +
                    std::to_string(RecipeFile::kFormatVersion) + " and older");
    const auto steps = recipe.find("steps");
    if (steps == recipe.end() || !steps->is_array())
        throw Error("the recipe has no list of \"steps\"");
    return *steps;
}

nlohmann::json parseRecipe(const std::string& text, const std::string& sourceName) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        throw Error(sourceName + " is not valid JSON: " + jsonread::parseErrorReason(error));
    } catch (const nlohmann::json::exception& error) {
        // E.g. out_of_range 406: a number like 1e999 that no double can hold.
        throw Error(sourceName +
                    " has a number out of range: " + jsonread::parseErrorReason(error));
    }
}

nlohmann::json readRecipeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read the recipe " + path);
    std::ostringstream text;
    text << in.rdbuf();
    return parseRecipe(text.str(), path);
}

void writeRecipeFile(const nlohmann::json& recipe, const std::string& path) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out)
            throw Error("cannot write " + path + ": the folder does not exist or is read-only");
        out << recipe.dump(2) << '\n';
        if (!out.flush())
            throw Error("cannot write " + path);
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw Error("cannot write " + path);
    }
}

void runRecipeFile(Document& document, const std::string& path,
                   const RecipeRunner::StepCallback& onStep, const recipe::StepOptions& options) {
    const nlohmann::json recipe = readRecipeFile(path);
    RecipeRunner(document, std::filesystem::path(path).parent_path(), options).run(recipe, onStep);
}

}  // namespace rigmesh::model
