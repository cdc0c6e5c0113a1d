#include "io/ExportFormat.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "base/Error.h"

namespace rigmesh {

ExportFormat exportFormatFromPath(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".glb")
        return ExportFormat::Glb;
    if (extension == ".gltf")
        return ExportFormat::Gltf;
    if (extension == ".fbx")
        return ExportFormat::Fbx;
    if (extension == ".dae")
        return ExportFormat::Collada;
    if (extension == ".obj")
        return ExportFormat::Obj;
    throw Error(MessageId::ExportUnknownFormat, path, extension);
}

bool isRiggedFormat(ExportFormat format) {
    return format != ExportFormat::Obj;
}

int formatInfluenceLimit(ExportFormat format) {
    return format == ExportFormat::Glb || format == ExportFormat::Gltf ? 4 : 0;
}

int effectiveInfluenceLimit(ExportFormat format, int requested) {
    const int limit = formatInfluenceLimit(format);
    if (requested <= 0)
        return limit;
    return limit == 0 ? requested : std::min(limit, requested);
}

}  // namespace rigmesh
