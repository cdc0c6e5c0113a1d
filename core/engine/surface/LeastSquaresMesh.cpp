#include "surface/LeastSquaresMesh.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <algorithm>

#include "base/Error.h"

namespace rigmesh {
namespace {

std::vector<std::vector<int>> oneRings(const TriMesh& mesh) {
    std::vector<std::vector<int>> ring(mesh.vertices.size());
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            ring[f[k]].push_back(f[(k + 1) % 3]);
            ring[f[k]].push_back(f[(k + 2) % 3]);
        }
    for (auto& neighbours : ring) {
        std::sort(neighbours.begin(), neighbours.end());
        neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
    }
    return ring;
}

}  // namespace

std::vector<Vec3> leastSquaresMesh(const TriMesh& mesh, const std::vector<double>& anchorWeights,
                                   double fixedWeight) {
    const int n = mesh.vertexCount();
    if (std::none_of(anchorWeights.begin(), anchorWeights.end(), [](double w) { return w > 0; }))
        throw Error(MessageId::SmoothingNeedsAnchor);

    // Unknowns: the vertices not held exactly.
    std::vector<int> unknown(n, -1);
    int unknowns = 0;
    for (int i = 0; i < n; ++i)
        if (anchorWeights[i] < fixedWeight)
            unknown[i] = unknowns++;
    std::vector<Vec3> positions = mesh.vertices;
    if (unknowns == 0)
        return positions;

    // Umbrella operator rows (L x)_i = x_i - mean of the one-ring, split into
    // the columns of unknown vertices (L_U) and the known part L_K x_K.
    const auto ring = oneRings(mesh);
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::MatrixX3d knownPart = Eigen::MatrixX3d::Zero(n, 3);
    auto add = [&](int row, int column, double value) {
        if (unknown[column] >= 0)
            entries.emplace_back(row, unknown[column], value);
        else
            knownPart.row(row) += value * mesh.vertices[column].transpose();
    };
    for (int i = 0; i < n; ++i) {
        if (ring[i].empty())
            continue;
        add(i, i, 1.0);
        for (int j : ring[i])
            add(i, j, -1.0 / static_cast<double>(ring[i].size()));
    }
    Eigen::SparseMatrix<double> laplacian(n, unknowns);
    laplacian.setFromTriplets(entries.begin(), entries.end());

    Eigen::SparseMatrix<double> system = laplacian.transpose() * laplacian;
    Eigen::MatrixX3d rhs = -(laplacian.transpose() * knownPart);
    for (int i = 0; i < n; ++i) {
        const int u = unknown[i];
        const double w2 = anchorWeights[i] * anchorWeights[i];
        if (u < 0 || w2 <= 0)
            continue;
        system.coeffRef(u, u) += w2;
        rhs.row(u) += w2 * mesh.vertices[i].transpose();
    }
    // Simplicial for small systems, supernodal (BLAS blocks) once the fill-in
    // of L^T L makes dense blocks worth it.
    constexpr int kSupernodalFrom = 4000;
    Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> solver;
    solver.setMode(unknowns >= kSupernodalFrom ? Eigen::CholmodSupernodalLLt
                                               : Eigen::CholmodSimplicialLLt);
    // AMD alone: CHOLMOD's default also tries METIS, which costs more than
    // it saves at these sizes.
    solver.cholmod().nmethods = 1;
    solver.cholmod().method[0].ordering = CHOLMOD_AMD;
    solver.compute(system);
    if (solver.info() != Eigen::Success)
        throw Error(MessageId::SurfaceSmoothingNotFactored);
    Eigen::MatrixX3d solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
        throw Error(MessageId::SurfaceSmoothingNoSolution);

    for (int i = 0; i < n; ++i)
        if (unknown[i] >= 0)
            positions[i] = solution.row(unknown[i]).transpose();
    return positions;
}

}  // namespace rigmesh
