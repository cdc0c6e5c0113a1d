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
        throw Error(MessageId::RecipeNotARecipe, RecipeFile::kFormatName);
    const auto version = recipe.find("version");
    if (version == recipe.end() || !version->is_number_integer() ||
        version->get<std::int64_t>() < 1)
        throw Error(MessageId::RecipeNoVersion);
    if (version->get<std::int64_t>() > RecipeFile::kFormatVersion)
        throw Error(MessageId::RecipeVersionTooNew, version->get<std::int64_t>(),
                    RecipeFile::kFormatVersion);
    const auto steps = recipe.find("steps");
    if (steps == recipe.end() || !steps->is_array())
        throw Error(MessageId::RecipeNoSteps);
    return *steps;
}

nlohmann::json parseRecipe(const std::string& text, const std::string& sourceName) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& error) {
        throw Error(
            Message{MessageId::RecipeNotJson, {sourceName}, {jsonread::parseErrorReason(error)}});
    } catch (const nlohmann::json::exception& error) {
        // E.g. out_of_range 406: a number like 1e999 that no double can hold.
        throw Error(Message{
            MessageId::RecipeNumberOutOfRange, {sourceName}, {jsonread::parseErrorReason(error)}});
    }
}

nlohmann::json readRecipeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error(MessageId::RecipeCannotRead, path);
    std::ostringstream text;
    text << in.rdbuf();
    return parseRecipe(text.str(), path);
}

void writeRecipeFile(const nlohmann::json& recipe, const std::string& path) {
    const std::string temporary = path + ".tmp";
    {
        std::ofstream out(temporary, std::ios::binary);
        if (!out)
            throw Error(MessageId::RecipeCannotWriteFolder, path);
        out << recipe.dump(2) << '\n';
        if (!out.flush())
            throw Error(MessageId::RecipeCannotWrite, path);
    }
    std::error_code error;
    std::filesystem::rename(temporary, path, error);
    if (error) {
        std::filesystem::remove(temporary, error);
        throw Error(MessageId::RecipeCannotWrite, path);
    }
}

void runRecipeFile(Document& document, const std::string& path,
                   const RecipeRunner::StepCallback& onStep, const recipe::StepOptions& options) {
    const nlohmann::json recipe = readRecipeFile(path);
    RecipeRunner(document, std::filesystem::path(path).parent_path(), options).run(recipe, onStep);
}

}  // namespace rigmesh::model
