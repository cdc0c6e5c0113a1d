// Least-Squares Meshes smoothing [Sorkine and Cohen-Or 2004] (paper 2.2, Fig. 3f).
//
// Finds positions x minimising ||L x||^2 + sum_i w_i^2 ||x_i - c_i||^2, where
// L is the uniform (umbrella) Laplacian of the mesh and c_i the current
// positions. Vertices with weight 0 are free. The normal equations
// (L^T L + W^2) x = W^2 c are factored once with CHOLMOD and solved for x, y, z.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Returns the smoothed positions. Throws rigmesh::Error when no vertex is
// anchored (the system is then singular) or the factorisation fails.
std::vector<Vec3> leastSquaresMesh(const TriMesh& mesh, const std::vector<double>& anchorWeights);

}  // namespace rigmesh
