#include "mesh/MeshFileFormat.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "base/Error.h"

namespace rigmesh {

MeshFileFormat meshFileFormatFromPath(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".obj")
        return MeshFileFormat::Obj;
    if (extension == ".off")
        return MeshFileFormat::Off;
    if (extension == ".ply")
        return MeshFileFormat::Ply;
    throw Error(MessageId::MeshFileTypeUnsupported, extension.empty() ? path : extension);
}

}  // namespace rigmesh
