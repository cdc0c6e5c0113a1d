#include "RunCommand.h"

#include <QCoreApplication>
#include <QString>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <optional>

#include "CommandLine.h"
#include "DocumentOutput.h"
#include "base/Error.h"
#include "base/StagedFile.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/recipe/RecipeFile.h"

namespace rigmesh::cli {

int runRecipe(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--stats"},
                     {"--compare-global", "--leaf-bones", "--no-leaf-bones", "--linear-blend",
                      "--dual-quaternion"});
    if (line.positional().size() != 1)
        throw Error("run needs exactly one recipe file (.json)");
    const std::string recipePath = line.positional()[0];
    const std::optional<std::string> out = line.value("-o");
    if (out)
        checkDocumentOutputPath(*out, true);  // an unknown extension fails before any step runs
    ExportOptions exportSettings;
    exportSettings.leafBones = leafBonesOption(line);
    exportSettings.skinning = skinningOption(line);
    const auto application = ensureCoreApplication();  // the commands translate their texts

    const std::optional<std::string> statsPath = line.value("--stats");
    model::recipe::StepOptions options;
    options.compareGlobalReskin = line.flag("--compare-global");

    model::Document document;
    int steps = 0;
    nlohmann::json stats = {{"recipe", recipePath}, {"steps", nlohmann::json::array()}};
    model::runRecipeFile(
        document, recipePath,
        [&](const model::RecipeStepReport& report) {
            ++steps;
            std::printf("step %d (%s): %s\n", report.number, report.command.c_str(),
                        report.summary.c_str());
            nlohmann::json step = {
                {"step", report.number}, {"command", report.command}, {"ms", report.milliseconds}};
            if (!report.stats.is_null())
                step[report.command] = report.stats;
            stats["steps"].push_back(std::move(step));
        },
        options);
    if (statsPath)
        writeFileAtomically(*statsPath, stats.dump(2) + "\n");
    std::printf("%d step%s, %d part%s\n", steps, steps == 1 ? "" : "s", document.partCount(),
                document.partCount() == 1 ? "" : "s");
    if (out)
        writeDocumentOutput(document, *out, exportSettings);
    return 0;
}

}  // namespace rigmesh::cli
