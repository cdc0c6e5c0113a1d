#include "model/recipe/RecipeRunner.h"

#include <QUndoStack>
#include <chrono>
#include <filesystem>
#include <utility>

#include "base/JsonRead.h"
#include "base/Stopwatch.h"
#include "model/GuardedUndo.h"
#include "model/recipe/RecipeFile.h"
#include "model/recipe/RecipeStepCommands.h"

namespace rigmesh::model {

namespace {

// What a step's message names as its command when it has none.
constexpr const char* kNoCommand = "?";

std::string stepCommandName(const nlohmann::json& step, int number) {
    if (!step.is_object())
        throw RecipeError(number, kNoCommand, Message{MessageId::RecipeStepNotObject, {}, {}});
    const auto it = step.find("command");
    if (it == step.end())
        throw RecipeError(number, kNoCommand, Message{MessageId::RecipeStepNoCommand, {}, {}});
    if (!it->is_string())
        throw RecipeError(number, kNoCommand, Message{MessageId::RecipeStepCommandNotText, {}, {}});
    return it->get<std::string>();
}

std::string summaryOf(const Document& document, const std::string& command, const QString& text,
                      const recipe::StepCommand& made) {
    std::string summary = text.toStdString();
    if (command == "sketch" && document.contains(made.part)) {
        const PartNode& node = document.part(made.part);
        summary += ": " + std::to_string(node.part->mesh.vertexCount()) + " vertices, " +
                   std::to_string(node.part->skeleton.jointCount()) + " joints";
    }
    if (!made.detail.empty())
        summary += ": " + made.detail;
    return summary;
}

}  // namespace

RecipeRunner::RecipeRunner(Document& document, std::filesystem::path baseDirectory,
                           recipe::StepOptions options)
    : document_(document), baseDirectory_(std::move(baseDirectory)), options_(options) {}

void RecipeRunner::run(const nlohmann::json& recipe, const StepCallback& onStep) {
    const nlohmann::json& steps = recipeSteps(recipe);
    // Steps of older versions keep their meaning (RecipeStepCommands.h).
    recipe::StepOptions options = options_;
    options.formatVersion = recipe["version"].get<int>();
    int number = 0;
    for (const nlohmann::json& step : steps) {
        const RecipeStepReport report = apply(step, ++number, options);
        if (onStep)
            onStep(report);
    }
}

RecipeStepReport RecipeRunner::apply(const nlohmann::json& step, int number) {
    return apply(step, number, options_);
}

RecipeStepReport RecipeRunner::apply(const nlohmann::json& step, int number,
                                     const recipe::StepOptions& options) {
    const std::string command = stepCommandName(step, number);
    recipe::StepCommand made;
    QString text;
    const auto start = std::chrono::steady_clock::now();
    try {
        made = recipe::commandForStep(document_, command, step, baseDirectory_, options);
        text = made.command->text();
        // A redo() that throws leaves the document as it was (GuardedUndo).
        pushCommand(document_, std::move(made.command));
    } catch (const RecipeError&) {
        throw;
    } catch (const nlohmann::json::exception& error) {
        throw RecipeError(number, command, jsonread::parseErrorReason(error));
    } catch (const Error& error) {
        throw RecipeError(number, command, messageOf(error));
    } catch (const std::filesystem::filesystem_error& error) {
        throw RecipeError(number, command, messageOf(error));
    }
    // Anything else (std::logic_error: a programming error; std::bad_alloc)
    // goes on as it is, so the command line reports it as an internal error or
    // as out of memory, not as a fault of the recipe (app/cli/CommandFailure.cpp).
    const double milliseconds = millisecondsSince(start);
    return {number, command, summaryOf(document_, command, text, made), milliseconds,
            std::move(made.stats)};
}

}  // namespace rigmesh::model
