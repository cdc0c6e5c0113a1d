// Least-Squares Meshes smoothing [Sorkine and Cohen-Or 2004] (paper 2.2, Fig. 3f).
//
// Finds positions x minimising ||L x||^2 + sum_i w_i^2 ||x_i - c_i||^2, where
// L is the uniform (umbrella) Laplacian of the mesh and c_i the current
// positions. Vertices with weight 0 are free.
//
// Vertices whose weight is at least `fixedWeight` are held exactly instead of
// softly: at the surface builder's maximum weight their soft displacement is
// far below an edge length, and dropping them from the unknowns makes the
// solve local to the connecting regions, which is what keeps it fast on long
// parts (the normal equations of L^T L fill in heavily along a tube). The
// remaining system (L_U^T L_U + W_U^2) x_U = W_U^2 c_U - L_U^T L_K x_K is
// factored once with CHOLMOD and solved for x, y and z.
#pragma once

#include <limits>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Returns the smoothed positions. Throws rigmesh::Error when no vertex is
// anchored (the system is then singular) or the factorisation fails.
//
// `mirror`, if given, is each vertex's image in the plane z = 0 (as
// SketchSurface::mirror gives it). When the mesh is exactly its own mirror
// image (mesh/MeshMirror.h) and every vertex has its image's weight, the
// minimiser is mirror-symmetric: x and y the same at a vertex and its image,
// z opposite (0 on the plane). It is then found among such positions,
// x_U = R u, by the normal equations R^T (L_U^T L_U + W_U^2) R u = R^T (...):
// for x and y with R summing a vertex and its image into one unknown, for z
// with R taking their difference (the plane's vertices held at 0). Two
// systems of about half the size, whose solution differs from the full one's
// by rounding only, and is exactly mirror-symmetric.
std::vector<Vec3> leastSquaresMesh(const TriMesh& mesh, const std::vector<double>& anchorWeights,
                                   double fixedWeight = std::numeric_limits<double>::infinity(),
                                   const std::vector<int>& mirror = {});

}  // namespace rigmesh
