// Mesh files on disk: OBJ, OFF and binary PLY (with optional per-vertex
// colours). Writing is atomic, so a failed export never leaves a half-written
// file where the user expects their mesh; reading accepts what writeMesh writes
// plus the common variants other tools produce, and rejects corrupt files with
// an Error instead of crashing.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

using VertexColor = std::array<std::uint8_t, 3>;  // red, green, blue

struct MeshWriteOptions {
    // One colour per vertex, or empty for none. Only PLY stores colours; the
    // other formats ignore them.
    std::vector<VertexColor> vertexColors;
};

// Writes `mesh` in the format named by the extension of `path` (.obj, .off or
// .ply, case-insensitive). Text formats store coordinates in the shortest form
// that reads back to the identical double; PLY is binary little-endian with
// double coordinates, so every format round-trips exactly. The file is written
// beside `path`, every write checked, and renamed over it only when complete,
// keeping its permissions (base/StagedFile.h). Throws Error on an unknown
// extension, invalid face indices, a non-finite coordinate, a colour count
// that does not match the vertex count, a read-only target or any I/O failure.
void writeMesh(const TriMesh& mesh, const std::string& path, const MeshWriteOptions& options = {});

// Reads an .obj, .off or .ply file (ASCII or binary little-endian PLY).
// Polygons are fan-triangulated. When `vertexColors` is given it receives the
// PLY red/green/blue vertex properties, or is cleared if the file has none.
// Throws Error naming the file and the problem for unreadable or corrupt input.
TriMesh readMesh(const std::string& path, std::vector<VertexColor>* vertexColors = nullptr);

}  // namespace rigmesh
