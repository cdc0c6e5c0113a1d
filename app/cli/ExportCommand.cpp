#include "ExportCommand.h"

#include <QCoreApplication>
#include <QString>
#include <cstdio>
#include <optional>

#include "CommandLine.h"
#include "DocumentOutput.h"
#include "base/Error.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"

namespace rigmesh::cli {

int runExport(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--max-influences", "--subdivide", "--decimate"},
                     {"--current-pose", "--pose-as-key", "--no-animation", "--hidden",
                      "--leaf-bones", "--no-leaf-bones", "--linear-blend", "--dual-quaternion"});
    if (line.positional().size() != 1)
        throw Error("export needs exactly one document (.rigmesh)");
    const std::string documentPath = line.positional()[0];
    const std::optional<std::string> out = line.value("-o");
    if (!out)
        throw Error("export needs an output file: -o OUT.glb|.gltf|.fbx|.dae|.obj");
    checkDocumentOutputPath(*out, false);
    // As the studio's export dialog sets them.
    ExportOptions options = exportOptions(line);
    options.restPose = !line.flag("--current-pose") && !line.flag("--pose-as-key");
    options.poseAsKey = line.flag("--pose-as-key");
    options.animation = !line.flag("--no-animation");

    const auto application = ensureCoreApplication();
    const auto document = model::DocumentFile::load(QString::fromStdString(documentPath));
    const bool visibleOnly = !line.flag("--hidden");
    for (const QString& warning :
         model::exportDocument(*document, *out, options, visibleOnly).warnings)
        std::fprintf(stderr, "rigmesh: warning: %s\n", warning.toStdString().c_str());
    int exported = 0;
    for (const model::PartNode& node : document->parts())
        exported += node.part && (node.visible || !visibleOnly) ? 1 : 0;
    std::printf("wrote %s (%d part%s)\n", out->c_str(), exported, exported == 1 ? "" : "s");
    return 0;
}

}  // namespace rigmesh::cli
