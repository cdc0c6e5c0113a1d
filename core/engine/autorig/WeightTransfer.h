// Skin weights carried from the surface a rig was computed on (a proxy,
// autorig/RigSurface) to the mesh the part keeps: each point takes the
// weights at its closest point of the surface, the three corners' weights
// blended by their barycentric coordinates (as MeshRepair's filled holes
// and the merge's new vertices take their sources). Only the .cpp sees
// CGAL (an AABB tree of the surface's triangles).
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "part/BoneWeights.h"

namespace rigmesh {

// Per point with `wanted` set (all when `wanted` is empty): the blended,
// normalised weights (sorted by bone id, summing to 1); an empty list for
// the others. `weights` has one list per surface vertex.
WeightsById weightsAtClosestPoints(const TriMesh& surface, const WeightsById& weights,
                                   const std::vector<Vec3>& points,
                                   const std::vector<char>& wanted = {});

}  // namespace rigmesh
