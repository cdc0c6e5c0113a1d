// Reading PLY (ASCII, binary little- and big-endian) into a TriMesh.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "mesh/MeshWriter.h"

namespace rigmesh {

// Parses the bytes of a PLY file: vertex x/y/z (and red/green/blue into
// `vertexColors` when given), face vertex_indices fan-triangulated; other
// elements and properties are skipped. Throws Error describing the problem,
// naming the file as `path`.
TriMesh readPly(std::string_view bytes, const std::string& path,
                std::vector<VertexColor>* vertexColors);

}  // namespace rigmesh
