#include "surface/LeastSquaresMesh.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <algorithm>

#include "base/Error.h"

namespace rigmesh {

std::vector<Vec3> leastSquaresMesh(const TriMesh& mesh, const std::vector<double>& anchorWeights) {
    const int n = mesh.vertexCount();
    if (std::none_of(anchorWeights.begin(), anchorWeights.end(), [](double w) { return w > 0; }))
        throw Error("least-squares smoothing needs at least one anchored vertex");

    // Umbrella operator: (L x)_i = x_i - mean of the one-ring neighbours.
    std::vector<std::vector<int>> ring(n);
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            ring[f[k]].push_back(f[(k + 1) % 3]);
            ring[f[k]].push_back(f[(k + 2) % 3]);
        }
    std::vector<Eigen::Triplet<double>> entries;
    for (int i = 0; i < n; ++i) {
        auto& neighbours = ring[i];
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
        entries.emplace_back(i, i, 1.0);
        for (int j : neighbours)
            entries.emplace_back(i, j, -1.0 / static_cast<double>(neighbours.size()));
    }
    Eigen::SparseMatrix<double> laplacian(n, n);
    laplacian.setFromTriplets(entries.begin(), entries.end());

    Eigen::SparseMatrix<double> system = laplacian.transpose() * laplacian;
    Eigen::MatrixX3d rhs = Eigen::MatrixX3d::Zero(n, 3);
    for (int i = 0; i < n; ++i) {
        double w2 = anchorWeights[i] * anchorWeights[i];
        if (w2 <= 0)
            continue;
        system.coeffRef(i, i) += w2;
        rhs.row(i) = w2 * mesh.vertices[i].transpose();
    }
    Eigen::CholmodSimplicialLLT<Eigen::SparseMatrix<double>> solver;
    // AMD alone: CHOLMOD's default also tries METIS, which costs more than
    // it saves on surface meshes of this size.
    solver.cholmod().nmethods = 1;
    solver.cholmod().method[0].ordering = CHOLMOD_AMD;
    solver.compute(system);
    if (solver.info() != Eigen::Success)
        throw Error("least-squares smoothing failed: the surface system could not be factored");
    Eigen::MatrixX3d solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
        throw Error("least-squares smoothing failed: the surface system has no finite solution");

    std::vector<Vec3> positions(n);
    for (int i = 0; i < n; ++i)
        positions[i] = solution.row(i).transpose();
    return positions;
}

}  // namespace rigmesh
