#include "RigCommand.h"

#include <QString>
#include <cstdio>
#include <filesystem>
#include <utility>

#include "CommandLine.h"
#include "DocumentOutput.h"
#include "base/Error.h"
#include "mesh/MeshWriter.h"
#include "model/Document.h"
#include "model/GuardedUndo.h"
#include "model/commands/ImportPartsCommand.h"
#include "model/commands/RigPartCommand.h"

namespace rigmesh::cli {

namespace {

// PROXY.obj for the first rig, PROXY_2.obj for the second, ...
std::string proxyPath(const std::string& path, int rig) {
    if (rig == 0)
        return path;
    const std::filesystem::path p(path);
    return (p.parent_path() /
            (p.stem().string() + "_" + std::to_string(rig + 1) + p.extension().string()))
        .string();
}

}  // namespace

int runRig(const std::vector<std::string>& arguments) {
    CommandLine line(arguments, {"-o", "--max-influences", "--debug-proxy"},
                     {"--leaf-bones", "--no-leaf-bones", "--separately"});
    if (line.positional().size() != 1)
        throw Error("rig needs exactly one mesh file to read");
    const std::optional<std::string> out = line.value("-o");
    if (!out)
        throw Error("rig needs -o OUT.rigmesh|.glb|.gltf|.fbx|.dae (the rigged result)");
    checkDocumentOutputPath(*out, true);
    const std::optional<std::string> proxy = line.value("--debug-proxy");
    if (proxy && std::filesystem::path(*proxy).extension() != ".obj")
        throw Error("--debug-proxy writes an .obj file, not " + *proxy);
    const ExportOptions options = exportOptions(line);
    const auto application = ensureCoreApplication();  // the commands translate their texts

    model::Document document;
    const QString path = QString::fromStdString(line.positional()[0]);
    auto import = model::ImportPartsCommand::create(document, path);
    std::vector<model::PartId> unrigged;
    for (const model::PartId id : import->partIds())
        unrigged.push_back(id);
    model::pushCommand(document, std::move(import));
    std::erase_if(unrigged, [&](model::PartId id) {
        return document.part(id).part->skeleton.jointCount() > 0;
    });
    if (unrigged.empty())
        throw Error(line.positional()[0] +
                    " has nothing to rig: every part in it already has a skeleton");
    std::vector<std::vector<model::PartId>> rigs;
    if (line.flag("--separately"))
        for (const model::PartId id : unrigged)
            rigs.push_back({id});
    else
        rigs.push_back(unrigged);
    for (std::size_t r = 0; r < rigs.size(); ++r) {
        auto command = model::RigPartCommand::create(document, rigs[r]);
        std::printf("%s\n", command->summary().toStdString().c_str());
        if (proxy)
            writeMesh(*command->result().rigSurface, proxyPath(*proxy, static_cast<int>(r)));
        model::pushCommand(document, std::move(command));
    }
    writeDocumentOutput(document, *out, options);
    return 0;
}

}  // namespace rigmesh::cli
