// Least-squares fairing: values at some vertices are chosen to minimise the
// squared uniform Laplacian over those vertices and their one ring, every
// other vertex held (Least-Squares Meshes, paper 2.2, without anchors). The
// merge smooths its seam band with it (3.2.1); a cut fills its patch's
// positions (smooth style) and skin weights with it (3.1).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// `values` has one row per vertex; the rows of `free` are replaced. Returns
// false (values untouched) if the system cannot be solved (a free vertex
// with no held vertex in reach).
bool fairValues(const TriMesh& mesh, const std::vector<int>& free, Eigen::MatrixXd& values);

// fairValues on the positions.
bool fairPositions(TriMesh& mesh, const std::vector<int>& free);

}  // namespace rigmesh
