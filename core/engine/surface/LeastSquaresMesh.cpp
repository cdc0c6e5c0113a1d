#include "surface/LeastSquaresMesh.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <algorithm>
#include <optional>

#include "base/Error.h"
#include "mesh/MeshMirror.h"

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

// Solves (A^T A + diag(anchorSquared)) X = rhs with CHOLMOD.
Eigen::MatrixXd solveNormalEquations(const Eigen::SparseMatrix<double>& a,
                                     const Eigen::VectorXd& anchorSquared,
                                     const Eigen::MatrixXd& rhs) {
    const auto unknowns = static_cast<int>(a.cols());
    Eigen::SparseMatrix<double> system = a.transpose() * a;
    for (int u = 0; u < unknowns; ++u)
        if (anchorSquared[u] > 0)
            system.coeffRef(u, u) += anchorSquared[u];
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
    Eigen::MatrixXd solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
        throw Error(MessageId::SurfaceSmoothingNoSolution);
    return solution;
}

// The mirror-symmetric solve (LeastSquaresMesh.h): `laplacian` is L_U,
// `rhs` the full right-hand side (unknowns x 3), `anchorSquared` W_U^2. Empty
// when the mesh and weights are not exactly mirror-symmetric.
std::optional<Eigen::MatrixX3d> solveMirrored(
    const TriMesh& mesh, const std::vector<double>& anchorWeights, const std::vector<int>& mirror,
    const std::vector<int>& unknown, const Eigen::SparseMatrix<double>& laplacian,
    const Eigen::VectorXd& anchorSquared, const Eigen::MatrixX3d& rhs) {
    if (mirror.empty() || !mirrorFaceImages(mesh, mirror))
        return std::nullopt;
    const int n = mesh.vertexCount();
    for (int v = 0; v < n; ++v)
        if (anchorWeights[v] != anchorWeights[mirror[v]])
            return std::nullopt;
    // R for x and y (a vertex and its image summed) and for z (the
    // representative, the smaller index, minus its image).
    std::vector<Eigen::Triplet<double>> sums, differences;
    int sumCount = 0, differenceCount = 0;
    for (int v = 0; v < n; ++v) {
        const int m = mirror[v];
        if (unknown[v] < 0 || m < v)
            continue;
        sums.emplace_back(unknown[v], sumCount, 1.0);
        if (m != v) {
            sums.emplace_back(unknown[m], sumCount, 1.0);
            differences.emplace_back(unknown[v], differenceCount, 1.0);
            differences.emplace_back(unknown[m], differenceCount, -1.0);
            ++differenceCount;
        }
        ++sumCount;
    }
    const auto unknowns = static_cast<int>(laplacian.cols());
    Eigen::SparseMatrix<double> sum(unknowns, sumCount), difference(unknowns, differenceCount);
    sum.setFromTriplets(sums.begin(), sums.end());
    difference.setFromTriplets(differences.begin(), differences.end());
    Eigen::MatrixX3d solution(unknowns, 3);
    // R^T W^2 R is diagonal: W is the same at a vertex and its image.
    const Eigen::VectorXd sumAnchors = sum.transpose() * anchorSquared;
    const Eigen::MatrixXd planar =
        solveNormalEquations(laplacian * sum, sumAnchors, sum.transpose() * rhs.leftCols<2>());
    solution.leftCols<2>() = sum * planar;
    if (differenceCount > 0) {
        const Eigen::VectorXd differenceAnchors =
            difference.cwiseAbs2().transpose() * anchorSquared;
        const Eigen::MatrixXd height = solveNormalEquations(
            laplacian * difference, differenceAnchors, difference.transpose() * rhs.col(2));
        solution.col(2) = difference * height;
    } else {
        solution.col(2).setZero();
    }
    return solution;
}

}  // namespace

std::vector<Vec3> leastSquaresMesh(const TriMesh& mesh, const std::vector<double>& anchorWeights,
                                   double fixedWeight, const std::vector<int>& mirror) {
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

    Eigen::MatrixX3d rhs = -(laplacian.transpose() * knownPart);
    Eigen::VectorXd anchorSquared = Eigen::VectorXd::Zero(unknowns);
    for (int i = 0; i < n; ++i) {
        const int u = unknown[i];
        const double w2 = anchorWeights[i] * anchorWeights[i];
        if (u < 0 || w2 <= 0)
            continue;
        anchorSquared[u] = w2;
        rhs.row(u) += w2 * mesh.vertices[i].transpose();
    }
    std::optional<Eigen::MatrixX3d> solution =
        solveMirrored(mesh, anchorWeights, mirror, unknown, laplacian, anchorSquared, rhs);
    if (!solution)
        solution = solveNormalEquations(laplacian, anchorSquared, rhs);

    for (int i = 0; i < n; ++i)
        if (unknown[i] >= 0)
            positions[i] = solution->row(unknown[i]).transpose();
    return positions;
}

}  // namespace rigmesh
