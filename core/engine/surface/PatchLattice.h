// The interior points of a connecting region's patch (cf. GridMesh, paper
// 2.2): a triangular lattice at the target edge length, keeping the points
// more than half an edge from the patch boundary.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

// `boundary` is a closed loop. Loops run over integer counts from the
// boundary's own box, and each point is tested only against the boundary
// segments in the grid cells around it, so the cost is linear in the number
// of lattice points plus the boundary's length in edges.
std::vector<Vec2> latticeInside(const std::vector<Vec2>& boundary, double edgeLength);

}  // namespace rigmesh
