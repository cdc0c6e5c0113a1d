// Joints the curve skeleton put outside the surface, pulled back in. The
// flow's medial attraction follows the Voronoi poles of the vertices, and at
// an unevenly meshed tip (a metaball's, from Blender) a pole can lie beyond
// the surface: the leaf joint ended 0.19 outside a limb 0.9 thick. A joint
// outside is moved along its bone towards the neighbouring joint until it is
// inside by `margin` (or halfway to that joint), so bones stay in the shape
// (paper 2.3: the skeleton lies inside).
#pragma once

#include <functional>

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// About 1 inside a closed outward mesh, 0 outside (the generalized winding
// number: the triangles' solid angles over 4 pi; Jacobson et al. 2013).
double windingNumber(const TriMesh& mesh, const Vec3& point);

// `margin(joint)`: how deep inside the joint should sit (its branch's
// radius, say). Returns how many joints moved.
int pullJointsInside(Skeleton& skeleton, const TriMesh& mesh,
                     const std::function<double(JointId)>& margin);

}  // namespace rigmesh
