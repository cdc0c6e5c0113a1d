// The winding number of a closed surface around a point, exactly: the
// signed count of the surface's crossings by a ray from the point along an axis (each face
// the ray leaves through along its normal counts +1, enters through -1),
// decided with exact predicates. For a surface whose directed edges cancel
// (every edge a->b matched by b->a, a 2-cycle) this is the integer that the
// generalized winding number (the triangles' solid angles over 4 pi,
// autorig/JointsInside.h; Jacobson et al. 2013) approximates in floating
// point, at the cost of a few comparisons per face instead of an atan2.
#pragma once

#include <optional>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// True when every directed edge a->b of the faces is matched by as many
// b->a: the faces bound, and the winding number is an integer off them.
bool directedEdgesCancel(const TriMesh& mesh);

// The winding number of `mesh` (its directed edges must cancel) around
// `point`, counted along the ray from it in +z, else +x, else +y; empty
// when each of those rays meets an edge or a vertex of a face, or the point
// lies on a face (then only the solid angles can say, and they are
// ill-conditioned on it).
std::optional<int> exactWindingNumber(const TriMesh& mesh, const Vec3& point);

// The same for many points, in one pass over the faces per axis (each face
// tested against the points within its box only).
std::vector<std::optional<int>> exactWindingNumbers(const TriMesh& mesh,
                                                    const std::vector<Vec3>& points);

}  // namespace rigmesh
