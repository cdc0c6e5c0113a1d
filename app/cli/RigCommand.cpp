#include "RigCommand.h"

#include <QString>
#include <cstdio>

#include "CommandLine.h"
#include "DocumentOutput.h"
#include "base/Error.h"
#include "model/Document.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/RigPartCommand.h"

namespace rigmesh::cli {

int runRig(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--max-influences"}, {"--leaf-bones"});
    if (line.positional().size() != 1)
        throw Error("rig needs exactly one mesh file to read");
    const std::optional<std::string> out = line.value("-o");
    if (!out)
        throw Error("rig needs -o OUT.rigmesh|.glb|.gltf|.fbx|.dae (the rigged result)");
    checkDocumentOutputPath(*out, true);
    const ExportOptions options = exportOptions(line);
    const auto application = ensureCoreApplication();  // the commands translate their texts

    model::Document document;
    const QString path = QString::fromStdString(line.positional()[0]);
    auto import = model::ImportPartsCommand::create(document, path);
    const std::vector<model::PartId> parts = import->partIds();
    document.undoStack()->push(import.release());
    int rigged = 0;
    for (const model::PartId id : parts) {
        if (document.part(id).part->skeleton.jointCount() > 0)
            continue;
        auto command = model::RigPartCommand::create(document, id);
        std::printf("%s\n", command->summary().toStdString().c_str());
        document.undoStack()->push(command.release());
        ++rigged;
    }
    if (rigged == 0)
        throw Error(line.positional()[0] +
                    " has nothing to rig: every part in it already has a skeleton");
    writeDocumentOutput(document, *out, options);
    return 0;
}

}  // namespace rigmesh::cli
