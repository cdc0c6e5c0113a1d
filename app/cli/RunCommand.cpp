#include "RunCommand.h"

#include <QCoreApplication>
#include <QString>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include "CommandLine.h"
#include "base/Error.h"
#include "io/ExportFormat.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"
#include "model/recipe/RecipeFile.h"

namespace rigmesh::cli {
namespace {

bool isNativeDocument(const std::string& path) {
    std::string suffix = std::filesystem::path(path).extension().string();
    for (char& c : suffix)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return suffix == std::string(".") + model::DocumentFile::kSuffix;
}

}  // namespace

int runRecipe(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o"}, {});
    if (line.positional().size() != 1)
        throw Error("run needs exactly one recipe file (.json)");
    const std::string recipePath = line.positional()[0];
    const std::optional<std::string> out = line.value("-o");
    if (out && !isNativeDocument(*out)) {
        try {
            exportFormatFromPath(*out);  // an unknown extension fails before any step runs
        } catch (const Error&) {
            throw Error("cannot write " + *out +
                        ": unknown format; use .rigmesh, .glb, .gltf, .fbx, .dae or .obj");
        }
    }

    // The commands translate their undo texts through QCoreApplication.
    static int argc = 1;
    static char name[] = "rigmesh";
    static char* argv[] = {name, nullptr};
    std::unique_ptr<QCoreApplication> application;
    if (!QCoreApplication::instance())
        application = std::make_unique<QCoreApplication>(argc, argv);

    model::Document document;
    int steps = 0;
    model::runRecipeFile(document, recipePath, [&steps](const model::RecipeStepReport& report) {
        ++steps;
        std::printf("step %d (%s): %s\n", report.number, report.command.c_str(),
                    report.summary.c_str());
    });
    std::printf("%d step%s, %d part%s\n", steps, steps == 1 ? "" : "s", document.partCount(),
                document.partCount() == 1 ? "" : "s");
    if (out) {
        if (isNativeDocument(*out))
            model::DocumentFile::write(document, QString::fromStdString(*out));
        else
            for (const QString& warning : model::exportDocument(document, *out).warnings)
                std::fprintf(stderr, "rigmesh: warning: %s\n", warning.toStdString().c_str());
        std::printf("wrote %s\n", out->c_str());
    }
    return 0;
}

}  // namespace rigmesh::cli
