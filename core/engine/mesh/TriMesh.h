// An indexed triangle mesh as a plain value: positions and counter-clockwise
// (outward-facing) triangles. Parts hold it by value so that undo is a pointer
// swap and GPU upload is a memcpy; algorithms that need half-edge topology
// (CGAL) convert at their own edge.
#pragma once

#include <array>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct TriMesh {
    std::vector<Vec3> vertices;
    std::vector<std::array<int, 3>> faces;

    int vertexCount() const { return static_cast<int>(vertices.size()); }
    int faceCount() const { return static_cast<int>(faces.size()); }
};

}  // namespace rigmesh
