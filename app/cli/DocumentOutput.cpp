#include "DocumentOutput.h"

#include <QCoreApplication>
#include <QString>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "base/Error.h"
#include "io/ExportFormat.h"
#include "model/Document.h"
#include "model/DocumentExport.h"
#include "model/DocumentFile.h"

namespace rigmesh::cli {

bool leafBonesOption(const CommandLine& line) {
    // As Blender's own FBX exporter ("Add Leaf Bones" on): without end bones
    // Blender's glTF and FBX importers give a leaf its parent's length
    // (docs/EXCHANGE.md, "Leaf bones in Blender").
    if (line.flag("--no-leaf-bones") && line.flag("--leaf-bones"))
        throw Error("choose one: --leaf-bones or --no-leaf-bones");
    return !line.flag("--no-leaf-bones");
}

SkinningMethod skinningOption(const CommandLine& line) {
    // The studio's view skinning by default: linear blend, as glTF viewers
    // and Blender deform (docs/EXCHANGE.md, "Skinning in Blender").
    if (!line.flag("--dual-quaternion"))
        return SkinningMethod::LinearBlend;
    if (line.flag("--linear-blend"))
        throw Error("choose one skinning: --linear-blend or --dual-quaternion");
    return SkinningMethod::DualQuaternion;
}

ExportOptions exportOptions(const CommandLine& line) {
    ExportOptions options;
    if (auto influences = line.number("--max-influences")) {
        // Checked before the cast: converting a double outside int's range is undefined.
        constexpr double kMostInfluences = 1e6;
        if (*influences < 0 || *influences != std::floor(*influences) ||
            *influences > kMostInfluences)
            throw Error(
                "--max-influences must be a whole number from 0 to 1000000 (0 = all the format "
                "allows)");
        options.maxInfluences = static_cast<int>(*influences);
    }
    options.leafBones = leafBonesOption(line);
    options.skinning = skinningOption(line);
    if (auto levels = line.number("--subdivide")) {
        if (*levels < 0 || *levels > 4 || *levels != std::floor(*levels))
            throw Error("--subdivide must be a whole number from 0 to 4");
        options.subdivisionLevels = static_cast<int>(*levels);
    }
    if (auto faces = line.number("--decimate")) {
        if (*faces < 4 || *faces > 1e8 || *faces != std::floor(*faces))
            throw Error("--decimate must be a whole number of faces from 4 to 100000000");
        options.decimateToFaces = static_cast<int>(*faces);
    }
    return options;
}

bool isNativeDocument(const std::string& path) {
    std::string suffix = std::filesystem::path(path).extension().string();
    for (char& c : suffix)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return suffix == std::string(".") + model::DocumentFile::kSuffix;
}

void checkDocumentOutputPath(const std::string& path, bool allowNative) {
    if (allowNative && isNativeDocument(path))
        return;
    try {
        exportFormatFromPath(path);
    } catch (const Error&) {
        throw Error("cannot write " + path + ": unknown format; use " +
                    (allowNative ? ".rigmesh, " : "") + ".glb, .gltf, .fbx, .dae or .obj");
    }
}

void writeDocumentOutput(const model::Document& document, const std::string& path,
                         const ExportOptions& options) {
    if (isNativeDocument(path))
        model::DocumentFile::write(document, QString::fromStdString(path));
    else
        for (const QString& warning : model::exportDocument(document, path, options).warnings)
            std::fprintf(stderr, "rigmesh: warning: %s\n", warning.toStdString().c_str());
    std::printf("wrote %s\n", path.c_str());
}

std::unique_ptr<QCoreApplication> ensureCoreApplication() {
    static int argc = 1;
    static char name[] = "rigmesh";
    static char* argv[] = {name, nullptr};
    if (QCoreApplication::instance())
        return nullptr;
    return std::make_unique<QCoreApplication>(argc, argv);
}

}  // namespace rigmesh::cli
