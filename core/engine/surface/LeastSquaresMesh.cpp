#include "surface/LeastSquaresMesh.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Sparse>
#include <algorithm>
#include <optional>
#include <utility>

#include "base/Error.h"
#include "mesh/MeshMirror.h"

namespace rigmesh {
namespace {

// The one-rings (sorted neighbour indices) of the vertices marked in
// `wanted`, as offsets into one array: ring of v = neighbours[start[v] ..
// start[v + 1]), empty for a vertex not wanted.
struct OneRings {
    std::vector<int> start, neighbours;
    int size(int v) const { return start[v + 1] - start[v]; }
};

OneRings oneRings(const TriMesh& mesh, const std::vector<char>& wanted) {
    const int n = mesh.vertexCount();
    OneRings rings;
    std::vector<int> capacity(n + 1, 0);
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k)
            if (wanted[f[k]])
                capacity[f[k] + 1] += 2;
    for (int v = 0; v < n; ++v)
        capacity[v + 1] += capacity[v];
    std::vector<int> all(capacity[n]);
    std::vector<int> next(capacity.begin(), capacity.end() - 1);
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k)
            if (wanted[f[k]]) {
                all[next[f[k]]++] = f[(k + 1) % 3];
                all[next[f[k]]++] = f[(k + 2) % 3];
            }
    rings.start.assign(n + 1, 0);
    rings.neighbours.reserve(all.size());
    for (int v = 0; v < n; ++v) {
        const auto begin = all.begin() + capacity[v], end = all.begin() + capacity[v + 1];
        std::sort(begin, end);
        rings.neighbours.insert(rings.neighbours.end(), begin, std::unique(begin, end));
        rings.start[v + 1] = static_cast<int>(rings.neighbours.size());
    }
    return rings;
}

// Eigen's CHOLMOD decomposition, also analysed with a fill-reducing order
// the caller gives (CHOLMOD_GIVEN, postordered as CHOLMOD does its own), and
// telling the order it used.
class CholmodSolver : public Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>> {
  public:
    void analyzePattern(const Eigen::SparseMatrix<double>& matrix, std::vector<int>& order) {
        if (m_cholmodFactor) {
            cholmod_free_factor(&m_cholmodFactor, &cholmod());
            m_cholmodFactor = nullptr;
        }
        cholmod_sparse a = Eigen::viewAsCholmod(matrix.selfadjointView<Eigen::Lower>());
        cholmod().nmethods = 1;
        cholmod().method[0].ordering = CHOLMOD_GIVEN;
        m_cholmodFactor = cholmod_analyze_p(&a, order.data(), nullptr, 0, &cholmod());
        m_isInitialized = true;
        m_info = m_cholmodFactor ? Eigen::Success : Eigen::NumericalIssue;
        m_analysisIsOk = m_cholmodFactor != nullptr;
        m_factorizationIsOk = false;
    }
    // The permutation of the factor (empty before an analysis).
    std::vector<int> order() const {
        if (!m_cholmodFactor || !m_cholmodFactor->Perm)
            return {};
        const int* perm = static_cast<const int*>(m_cholmodFactor->Perm);
        return std::vector<int>(perm, perm + m_cholmodFactor->n);
    }
};

// Solves (A^T A + diag(anchorSquared)) X = rhs with CHOLMOD: with AMD's
// order, or `givenOrder` if not empty. `usedOrder`, if given, receives the
// factor's order.
Eigen::MatrixXd solveNormalEquations(const Eigen::SparseMatrix<double>& a,
                                     const Eigen::VectorXd& anchorSquared,
                                     const Eigen::MatrixXd& rhs, std::vector<int> givenOrder = {},
                                     std::vector<int>* usedOrder = nullptr) {
    const auto unknowns = static_cast<int>(a.cols());
    Eigen::SparseMatrix<double> system = a.transpose() * a;
    for (int u = 0; u < unknowns; ++u)
        if (anchorSquared[u] > 0)
            system.coeffRef(u, u) += anchorSquared[u];
    // Simplicial for small systems, supernodal (BLAS blocks) once the fill-in
    // of L^T L makes dense blocks worth it.
    constexpr int kSupernodalFrom = 4000;
    CholmodSolver solver;
    solver.setMode(unknowns >= kSupernodalFrom ? Eigen::CholmodSupernodalLLt
                                               : Eigen::CholmodSimplicialLLt);
    if (givenOrder.empty()) {
        // AMD alone: CHOLMOD's default also tries METIS, which costs more
        // than it saves at these sizes.
        solver.cholmod().nmethods = 1;
        solver.cholmod().method[0].ordering = CHOLMOD_AMD;
        solver.Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>>::analyzePattern(system);
    } else {
        solver.analyzePattern(system, givenOrder);
    }
    if (solver.info() != Eigen::Success)
        throw Error(MessageId::SurfaceSmoothingNotFactored);
    if (usedOrder)
        *usedOrder = solver.order();
    solver.factorize(system);
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
    std::vector<int> differenceOf;  // per sum unknown: its difference unknown, or -1
    int sumCount = 0, differenceCount = 0;
    for (int v = 0; v < n; ++v) {
        const int m = mirror[v];
        if (unknown[v] < 0 || m < v)
            continue;
        sums.emplace_back(unknown[v], sumCount, 1.0);
        differenceOf.push_back(m != v ? differenceCount : -1);
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
    std::vector<int> planarOrder;
    const Eigen::MatrixXd planar = solveNormalEquations(
        laplacian * sum, sumAnchors, sum.transpose() * rhs.leftCols<2>(), {}, &planarOrder);
    solution.leftCols<2>() = sum * planar;
    if (differenceCount > 0) {
        const Eigen::VectorXd differenceAnchors =
            difference.cwiseAbs2().transpose() * anchorSquared;
        // The z system's pattern is the x, y one's without the plane's
        // vertices (a difference column has the nonzeros of the matching sum
        // column, barring cancellation): the x, y system's AMD order without
        // them serves it, and its own AMD is not run.
        std::vector<int> heightOrder;
        heightOrder.reserve(differenceCount);
        for (int s : planarOrder)
            if (differenceOf[s] >= 0)
                heightOrder.push_back(differenceOf[s]);
        if (static_cast<int>(heightOrder.size()) != differenceCount)
            heightOrder.clear();
        const Eigen::MatrixXd height =
            solveNormalEquations(laplacian * difference, differenceAnchors,
                                 difference.transpose() * rhs.col(2), std::move(heightOrder));
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
    // Only rows with an unknown in them count: those of the vertices of
    // faces with an unknown corner (any other row of L_U is empty, and
    // L_K x_K there is never used).
    std::vector<char> rowUsed(n, 0);
    for (const auto& f : mesh.faces)
        if (unknown[f[0]] >= 0 || unknown[f[1]] >= 0 || unknown[f[2]] >= 0)
            rowUsed[f[0]] = rowUsed[f[1]] = rowUsed[f[2]] = 1;
    const OneRings ring = oneRings(mesh, rowUsed);
    // L_U written straight into compressed columns: the rows are visited in
    // order, so each column's rows come sorted; a row meeting a column twice
    // (a face with a repeated corner puts the vertex in its own ring) sums
    // its entries in the order setFromTriplets did, so L_U is what it was
    // bit for bit without the triplets and their transposed copy.
    std::vector<int> columnStart(static_cast<std::size_t>(unknowns) + 1, 0);
    for (int i = 0; i < n; ++i) {
        if (ring.size(i) == 0)
            continue;
        if (unknown[i] >= 0)
            ++columnStart[unknown[i] + 1];
        for (int k = ring.start[i]; k < ring.start[i + 1]; ++k)
            if (unknown[ring.neighbours[k]] >= 0)
                ++columnStart[unknown[ring.neighbours[k]] + 1];
    }
    for (int u = 0; u < unknowns; ++u)
        columnStart[u + 1] += columnStart[u];
    std::vector<int> rows(columnStart[unknowns]);
    std::vector<double> values(rows.size());
    std::vector<int> next(columnStart.begin(), columnStart.end() - 1);
    bool repeated = false;
    Eigen::MatrixX3d knownPart = Eigen::MatrixX3d::Zero(n, 3);
    auto add = [&](int row, int column, double value) {
        const int u = unknown[column];
        if (u < 0) {
            knownPart.row(row) += value * mesh.vertices[column].transpose();
        } else if (next[u] > columnStart[u] && rows[next[u] - 1] == row) {
            values[next[u] - 1] += value;
            repeated = true;
        } else {
            rows[next[u]] = row;
            values[next[u]++] = value;
        }
    };
    for (int i = 0; i < n; ++i) {
        const int size = ring.size(i);
        if (size == 0)
            continue;
        add(i, i, 1.0);
        for (int k = ring.start[i]; k < ring.start[i + 1]; ++k)
            add(i, ring.neighbours[k], -1.0 / static_cast<double>(size));
    }
    if (repeated) {  // close the gaps the sums left
        int written = 0;
        for (int u = 0; u < unknowns; ++u) {
            const int from = columnStart[u], to = next[u];
            columnStart[u] = written;
            for (int k = from; k < to; ++k, ++written) {
                rows[written] = rows[k];
                values[written] = values[k];
            }
        }
        columnStart[unknowns] = written;
    }
    Eigen::SparseMatrix<double> laplacian(n, unknowns);
    laplacian.resizeNonZeros(columnStart[unknowns]);
    std::copy(columnStart.begin(), columnStart.end(), laplacian.outerIndexPtr());
    std::copy(rows.begin(), rows.begin() + columnStart[unknowns], laplacian.innerIndexPtr());
    std::copy(values.begin(), values.begin() + columnStart[unknowns], laplacian.valuePtr());

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
