// A chain of bones along a mesh's main axis: the skeleton of a blob, where
// the curve skeleton has no branch to offer (a pebble, a bean, a duck's
// body) or the flow contracts it to a point. The axis is the principal
// direction of the vertices; the chain spans them between their 5th and
// 95th percentile along it, in bones about two radii long (one to four),
// pulled inside the surface (autorig/JointsInside), rooted in the middle.
#pragma once

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// `mesh` must be closed (the joints are pulled inside it). Throws
// Error(AutoRigTooFewVertices) for too few vertices and
// Error(AutoRigNoExtent) for a mesh without extent.
Skeleton mainAxisChain(const TriMesh& mesh);

// The largest distance from a vertex of `mesh` to the skeleton's bones (the
// coverage figure: a region far from every bone follows nothing).
double farthestFromBones(const TriMesh& mesh, const Skeleton& skeleton);

}  // namespace rigmesh
