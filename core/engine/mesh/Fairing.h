// Least-squares fairing: values at some vertices are chosen to minimise the
// squared uniform Laplacian over those vertices and their one ring, every
// other vertex held (Least-Squares Meshes, paper 2.2, without anchors). The
// merge smooths its seam band with it (3.2.1); a cut fills its patch's
// positions (smooth style) and skin weights with it (3.1).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// The system for a mesh's connectivity and its free vertices, factorised
// once, for several sets of values on the same vertices (a cut fairs its
// patch's positions, then its skin weights there).
class FairingSystem {
  public:
    FairingSystem(const TriMesh& mesh, const std::vector<int>& free);
    ~FairingSystem();
    FairingSystem(const FairingSystem&) = delete;
    FairingSystem& operator=(const FairingSystem&) = delete;

    const std::vector<int>& free() const;
    // `values` has one row per vertex; the rows of the free vertices are
    // replaced. Returns false (values untouched) if the system cannot be
    // solved (a free vertex with no held vertex in reach).
    bool solve(Eigen::MatrixXd& values) const;

  private:
    struct Factorised;
    std::unique_ptr<Factorised> factorised_;
};

// One FairingSystem's solve.
bool fairValues(const TriMesh& mesh, const std::vector<int>& free, Eigen::MatrixXd& values);

// fairValues on the positions.
bool fairPositions(TriMesh& mesh, const std::vector<int>& free);
// The same with a system factorised for this mesh's connectivity.
bool fairPositions(TriMesh& mesh, const FairingSystem& system);

}  // namespace rigmesh
