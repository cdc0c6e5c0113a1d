#include "mesh/Fairing.h"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCore>

#include <algorithm>

namespace rigmesh {

namespace {

// The rows of the system: every free vertex and its one ring (in order), and
// the neighbours of each (sorted, each once, as mesh/MeshAdjacency's
// vertexNeighbours gives them). Two passes over the faces instead of the
// whole mesh's adjacency: a cut's patch is a small part of its piece.
struct Rows {
    std::vector<int> vertices;
    std::vector<std::vector<int>> neighbours;  // per mesh vertex, filled for the rows only
};

Rows rowsAround(const TriMesh& mesh, const std::vector<int>& free) {
    const int n = mesh.vertexCount();
    std::vector<char> isFree(n, 0), isRow(n, 0);
    for (int v : free)
        isFree[v] = 1;
    for (const auto& face : mesh.faces)
        if (isFree[face[0]] || isFree[face[1]] || isFree[face[2]])
            for (int v : face)
                isRow[v] = 1;
    for (int v : free)
        isRow[v] = 1;
    Rows rows;
    rows.neighbours.resize(n);
    for (const auto& face : mesh.faces)
        for (int c = 0; c < 3; ++c)
            if (isRow[face[c]]) {
                rows.neighbours[face[c]].push_back(face[(c + 1) % 3]);
                rows.neighbours[face[c]].push_back(face[(c + 2) % 3]);
            }
    for (int v = 0; v < n; ++v)
        if (isRow[v]) {
            std::vector<int>& list = rows.neighbours[v];
            std::sort(list.begin(), list.end());
            list.erase(std::unique(list.begin(), list.end()), list.end());
            rows.vertices.push_back(v);
        }
    return rows;
}

}  // namespace

struct FairingSystem::Factorised {
    std::vector<int> free;
    // The held vertices' terms of each row, in the order the rows add them.
    struct HeldTerm {
        int row, vertex;
        double coefficient;
    };
    std::vector<HeldTerm> held;
    int rows = 0;
    Eigen::SparseMatrix<double> a;
    // CHOLMOD, as Least-Squares Meshes (2.2) and bone heat (2.4) use.
    Eigen::CholmodSimplicialLDLT<Eigen::SparseMatrix<double>> solver;
    bool factorised = false;
};

FairingSystem::FairingSystem(const TriMesh& mesh, const std::vector<int>& free)
    : factorised_(std::make_unique<Factorised>()) {
    Factorised& f = *factorised_;
    f.free = free;
    if (free.empty())
        return;
    const int n = mesh.vertexCount();
    std::vector<int> unknown(n, -1);
    for (std::size_t i = 0; i < free.size(); ++i)
        unknown[free[i]] = static_cast<int>(i);
    // Rows: the Laplacian at every free vertex and its one ring, so the fill
    // meets the held values with matching slope.
    const Rows around = rowsAround(mesh, free);
    const std::vector<std::vector<int>>& neighbours = around.neighbours;

    std::vector<Eigen::Triplet<double>> triplets;
    int row = 0;
    for (int v : around.vertices) {
        if (neighbours[v].empty())
            continue;
        const double inverseDegree = 1.0 / static_cast<double>(neighbours[v].size());
        auto add = [&](int vertex, double coefficient) {
            if (unknown[vertex] >= 0)
                triplets.emplace_back(row, unknown[vertex], coefficient);
            else
                f.held.push_back({row, vertex, coefficient});
        };
        add(v, 1.0);
        for (int w : neighbours[v])
            add(w, -inverseDegree);
        ++row;
    }
    f.rows = row;
    f.a.resize(row, static_cast<int>(free.size()));
    f.a.setFromTriplets(triplets.begin(), triplets.end());
    const Eigen::SparseMatrix<double> normal = f.a.transpose() * f.a;
    f.solver.compute(normal);
    f.factorised = f.solver.info() == Eigen::Success;
}

FairingSystem::~FairingSystem() = default;

const std::vector<int>& FairingSystem::free() const {
    return factorised_->free;
}

bool FairingSystem::solve(Eigen::MatrixXd& values) const {
    const Factorised& f = *factorised_;
    if (f.free.empty())
        return true;
    if (!f.factorised)
        return false;
    Eigen::MatrixXd heldPart = Eigen::MatrixXd::Zero(f.rows, values.cols());
    for (const Factorised::HeldTerm& term : f.held)
        heldPart.row(term.row) += term.coefficient * values.row(term.vertex);
    const Eigen::MatrixXd solution = f.solver.solve(-(f.a.transpose() * heldPart));
    if (f.solver.info() != Eigen::Success || !solution.allFinite())
        return false;
    for (std::size_t i = 0; i < f.free.size(); ++i)
        values.row(f.free[i]) = solution.row(static_cast<int>(i));
    return true;
}

bool fairValues(const TriMesh& mesh, const std::vector<int>& free, Eigen::MatrixXd& values) {
    return FairingSystem(mesh, free).solve(values);
}

bool fairPositions(TriMesh& mesh, const FairingSystem& system) {
    Eigen::MatrixXd positions(mesh.vertexCount(), 3);
    for (int v = 0; v < mesh.vertexCount(); ++v)
        positions.row(v) = mesh.vertices[v].transpose();
    if (!system.solve(positions))
        return false;
    for (int v : system.free())
        mesh.vertices[v] = positions.row(v).transpose();
    return true;
}

bool fairPositions(TriMesh& mesh, const std::vector<int>& free) {
    return fairPositions(mesh, FairingSystem(mesh, free));
}

}  // namespace rigmesh
