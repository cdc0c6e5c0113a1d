#include "rig/LocalBoneHeat.h"

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <set>

#include "base/Error.h"
#include "base/ParallelFor.h"
#include "mesh/MeshAdjacency.h"
#include "mesh/VertexNormals.h"
#include "rig/BoneSegments.h"
#include "rig/BoneVisibility.h"
#include "rig/HeatTerms.h"

namespace rigmesh {

namespace {

double weightOf(const std::vector<std::pair<BoneId, double>>& weights, BoneId bone) {
    for (const auto& [id, w] : weights)
        if (id == bone)
            return w;
    return 0.0;
}

// Paper 3.2.2's test: the vertex's closest visible bone(s) do not have above
// average weight (the average over its positive weights), so its weights
// are clearly not right any more. "Above" includes equal: a vertex wholly on
// its closest bone (one weight, 1 = the average) is right.
constexpr double kAverageTolerance = 1e-9;
bool failsInclusionTest(const std::vector<std::pair<BoneId, double>>& weights,
                        const std::vector<std::pair<BoneId, double>>& closest) {
    if (weights.empty())
        return true;
    const double average = 1.0 / static_cast<double>(weights.size());
    return std::none_of(closest.begin(), closest.end(), [&](const auto& c) {
        return weightOf(weights, c.first) >= average - kAverageTolerance;
    });
}

// The cotangent Laplacian rows of the unknown vertices with their one-ring
// areas, assembled from the faces touching them exactly as the global solver
// does (HeatTerms.h).
struct LocalSystem {
    std::vector<Eigen::Triplet<double>> unknownPart;            // among unknowns (both triangles)
    std::vector<std::vector<std::pair<int, double>>> heldPart;  // per unknown: (held vertex, L)
    std::vector<double> area;
};

LocalSystem assemble(const TriMesh& mesh, const std::vector<int>& unknownIndex, int unknownCount) {
    LocalSystem system;
    system.heldPart.resize(unknownCount);
    system.area.assign(unknownCount, 0.0);
    std::vector<double> diagonal(unknownCount, 0.0);
    auto addEdge = [&](int i, int k, double value) {
        // Row i of the symmetric L: L_ik += -value, L_ii += value.
        const int ui = unknownIndex[i];
        if (ui < 0)
            return;
        diagonal[ui] += value;
        const int uk = unknownIndex[k];
        if (uk >= 0)
            system.unknownPart.emplace_back(ui, uk, -value);
        else
            system.heldPart[ui].emplace_back(k, -value);
    };
    for (const auto& face : mesh.faces) {
        if (unknownIndex[face[0]] < 0 && unknownIndex[face[1]] < 0 && unknownIndex[face[2]] < 0)
            continue;
        const double doubleArea = usableDoubleArea(face, mesh.vertices);
        if (doubleArea == 0.0)
            continue;
        for (int c = 0; c < 3; ++c) {
            const int i = face[c], j = face[(c + 1) % 3], k = face[(c + 2) % 3];
            if (unknownIndex[i] >= 0)
                system.area[unknownIndex[i]] += 0.5 * doubleArea;
            const Vec3 e1 = mesh.vertices[j] - mesh.vertices[i];
            const Vec3 e2 = mesh.vertices[k] - mesh.vertices[i];
            const double halfCot = 0.5 * e1.dot(e2) / doubleArea;
            addEdge(j, k, halfCot);
            addEdge(k, j, halfCot);
        }
    }
    for (int u = 0; u < unknownCount; ++u)
        system.unknownPart.emplace_back(u, u, diagonal[u]);
    return system;
}

}  // namespace

LocalBoneHeatResult recomputeWeightsLocally(const TriMesh& mesh, const Skeleton& skeleton,
                                            WeightsById carriedWeights,
                                            const std::vector<int>& seeds,
                                            const std::vector<int>& unknown,
                                            const std::vector<BoneId>& extraBones,
                                            const LocalBoneHeatOptions& options) {
    if (skeleton.boneCount() == 0)
        throw Error(MessageId::WeightsNeedBone);
    // The result's table is the carried one, each re-skinned vertex's list
    // replaced after it has been read (the others are only read).
    LocalBoneHeatResult result;
    result.weights = std::move(carriedWeights);
    const WeightsById& weights = result.weights;
    const int n = mesh.vertexCount();
    std::vector<BoneId> allIds;
    for (const Bone& bone : skeleton.bones())
        allIds.push_back(bone.id);
    const std::vector<BoneSegment> allSegments = segmentsOf(skeleton, allIds);
    // The visibility tree over the whole part (half of a local re-skin at
    // the camel's last merge, measured with perf) is built while the
    // adjacency and the normals the visibility tests read are, on a second
    // thread (the normals once, not at every ring of the search below).
    std::optional<BoneVisibility> visibilityTree;
    std::vector<std::vector<int>> neighbours;
    std::vector<Vec3> normals;
    parallelFor(2, 2, [&](int begin, int end, int) {
        for (int k = begin; k < end; ++k) {
            if (k == 0) {
                visibilityTree.emplace(mesh);
            } else {
                neighbours = vertexNeighbours(mesh);
                normals = vertexNormals(mesh);
            }
        }
    });
    const BoneVisibility& visibility = *visibilityTree;
    auto closestOf = [&](const std::vector<int>& vertices) {
        ClosestBonesById byId(vertices.size());
        const auto found = closestVisibleBones(mesh, normals, allSegments, visibility, vertices,
                                               options.heat.tieTolerance);
        for (std::size_t i = 0; i < vertices.size(); ++i)
            for (const auto& [bone, d] : found[i])
                byId[i].emplace_back(allIds[bone], d);
        return byId;
    };

    // Red: breadth first from the merge boundary while the inclusion test
    // holds (paper 3.2.2); the seeds without weights are in regardless.
    std::vector<char> state(n, 0);  // 1 tested, 2 red, 3 yellow
    std::vector<double> closestDistance(n, 0.0);
    std::set<BoneId> involved(extraBones.begin(), extraBones.end());
    std::vector<char> mustInclude(n, 0);
    for (int v : unknown)
        mustInclude[v] = 1;
    std::vector<int> frontier;
    for (int v : seeds)
        if (!state[v]) {
            state[v] = 1;
            frontier.push_back(v);
        }
    for (int v : unknown)
        if (!state[v]) {
            state[v] = 1;
            frontier.push_back(v);
        }
    while (!frontier.empty()) {
        const ClosestBonesById closest = closestOf(frontier);
        std::vector<int> next;
        for (std::size_t i = 0; i < frontier.size(); ++i) {
            const int v = frontier[i];
            if (!mustInclude[v] && !failsInclusionTest(weights[v], closest[i]))
                continue;
            state[v] = 2;
            result.failedTest.push_back(v);
            closestDistance[v] = std::numeric_limits<double>::infinity();
            for (const auto& [bone, d] : closest[i]) {
                involved.insert(bone);
                closestDistance[v] = std::min(closestDistance[v], d);
            }
            for (int w : neighbours[v])
                if (!state[w]) {
                    state[w] = 1;
                    next.push_back(w);
                }
        }
        frontier = std::move(next);
    }

    // Yellow: within graph distance c * d(v_i, closest bone) of a red v_i,
    // by propagating the largest remaining budget (a Dijkstra on budgets).
    std::vector<double> budget(n, -1.0);
    std::priority_queue<std::pair<double, int>> queue;
    for (int v : result.failedTest) {
        budget[v] = options.transitionFactor * closestDistance[v];
        queue.emplace(budget[v], v);
    }
    while (!queue.empty()) {
        const auto [b, v] = queue.top();
        queue.pop();
        if (b < budget[v])
            continue;
        for (int w : neighbours[v]) {
            const double left = b - (mesh.vertices[w] - mesh.vertices[v]).norm();
            if (left > 0.0 && left > budget[w]) {
                budget[w] = left;
                queue.emplace(left, w);
            }
        }
    }
    for (int v = 0; v < n; ++v)
        if (budget[v] > 0.0 && state[v] != 2) {
            state[v] = 3;
            result.transition.push_back(v);
            const double average =
                1.0 / static_cast<double>(std::max<std::size_t>(weights[v].size(), 1));
            for (const auto& [bone, w] : weights[v])
                if (w >= average - kAverageTolerance)
                    involved.insert(bone);
        }

    // The unknowns and the bones of the local solve.
    std::vector<int> unknowns = result.failedTest;
    unknowns.insert(unknowns.end(), result.transition.begin(), result.transition.end());
    std::sort(unknowns.begin(), unknowns.end());
    result.bones.assign(involved.begin(), involved.end());
    if (unknowns.empty())
        return result;
    std::vector<int> unknownIndex(n, -1);
    for (std::size_t u = 0; u < unknowns.size(); ++u)
        unknownIndex[unknowns[u]] = static_cast<int>(u);
    const int m = static_cast<int>(unknowns.size());
    const std::vector<BoneSegment> involvedSegments = segmentsOf(skeleton, result.bones);
    // Pinocchio's heat sources among the involved bones only ("run on the
    // included vertices and bones").
    const auto heatSources = closestVisibleBones(mesh, normals, involvedSegments, visibility,
                                                 unknowns, options.heat.tieTolerance);

    LocalSystem system = assemble(mesh, unknownIndex, m);
    Eigen::VectorXd heat = Eigen::VectorXd::Zero(m);
    for (int u = 0; u < m; ++u) {
        double d = std::numeric_limits<double>::infinity();
        for (const auto& entry : heatSources[u])
            d = std::min(d, entry.second);
        heat[u] = system.area[u] > 0.0 && std::isfinite(d)
                      ? heatTerm(system.area[u], d, options.heat)
                      : 1.0;  // no usable triangle: w = p, as in the global solve
        system.unknownPart.emplace_back(u, u, heat[u]);
    }
    Eigen::SparseMatrix<double> matrix(m, m);
    matrix.setFromTriplets(system.unknownPart.begin(), system.unknownPart.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(matrix);
    if (solver.info() != Eigen::Success)
        throw Error(MessageId::LocalWeightsUnsolved);

    const int boneTotal = static_cast<int>(result.bones.size());
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(m, boneTotal);
    for (int u = 0; u < m; ++u) {
        for (const auto& [bone, d] : heatSources[u])
            rhs(u, bone) += heat[u] / static_cast<double>(heatSources[u].size());
        // The excluded neighbours' weights are boundary values (paper 3.2.2).
        for (const auto& [held, value] : system.heldPart[u])
            for (const auto& [bone, w] : weights[held]) {
                auto at = std::lower_bound(result.bones.begin(), result.bones.end(), bone);
                if (at != result.bones.end() && *at == bone)
                    rhs(u, at - result.bones.begin()) -= value * w;
            }
    }
    const Eigen::MatrixXd solution = solver.solve(rhs);
    if (solver.info() != Eigen::Success || !solution.allFinite())
        throw Error(MessageId::LocalWeightsUnsolved);

    for (int u = 0; u < m; ++u) {
        const int v = unknowns[u];
        std::vector<std::pair<BoneId, double>> updated;
        // Bones outside the solve keep their weight; solved bones are replaced.
        for (const auto& [bone, w] : weights[v])
            if (!std::binary_search(result.bones.begin(), result.bones.end(), bone))
                updated.emplace_back(bone, w);
        for (int b = 0; b < boneTotal; ++b) {
            const double w = taperedWeight(solution(u, b), options.heat);
            if (w > 0.0)
                updated.emplace_back(result.bones[b], w);
        }
        normaliseWeights(updated);
        if (updated.empty())  // everything tapered away: its closest bone
            updated.emplace_back(result.bones[heatSources[u].empty() ? 0 : heatSources[u][0].first],
                                 1.0);
        result.weights[v] = std::move(updated);
    }
    std::sort(result.failedTest.begin(), result.failedTest.end());
    return result;
}

WeightsById recomputeWeightsGlobally(const TriMesh& mesh, const Skeleton& skeleton,
                                     const BoneHeatOptions& options) {
    return weightsById(skeleton, computeBoneHeatWeights(mesh, segmentsOf(skeleton), {}, options))
        .perVertex;
}

}  // namespace rigmesh
