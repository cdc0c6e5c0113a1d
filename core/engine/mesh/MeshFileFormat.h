// The mesh file formats readMesh and writeMesh know, chosen by file extension.
#pragma once

#include <string>

namespace rigmesh {

enum class MeshFileFormat { Obj, Off, Ply };

// The format named by the extension of `path` (case-insensitive). Throws Error
// naming the supported extensions for anything else.
MeshFileFormat meshFileFormatFromPath(const std::string& path);

}  // namespace rigmesh
