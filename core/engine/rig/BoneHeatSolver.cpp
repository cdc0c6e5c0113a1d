#include "rig/BoneHeatSolver.h"

#include <Eigen/CholmodSupport>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "base/Error.h"
#include "base/ParallelFor.h"
#include "mesh/MeshMirror.h"
#include "mesh/VertexNormals.h"
#include "rig/BoneVisibility.h"
#include "rig/HeatTerms.h"
#include "rig/UpperFromTerms.h"

namespace rigmesh {

namespace {

// The heat of a vertex with only degenerate triangles, per edge weight.
constexpr double kOrphanHeatPerEdge = 1e-6;

// One CHOLMOD workspace. CHOLMOD is thread-safe when every thread has its own
// cholmod_common; the factor itself is only read by cholmod_solve2.
class CholmodCommon {
  public:
    CholmodCommon() {
        cholmod_start(&common_);
        common_.print = 0;  // report through our warning, never stdout
    }
    ~CholmodCommon() { cholmod_finish(&common_); }
    CholmodCommon(const CholmodCommon&) = delete;
    CholmodCommon& operator=(const CholmodCommon&) = delete;
    cholmod_common* get() { return &common_; }

  private:
    cholmod_common common_;
};

// Reusable dense workspaces of cholmod_solve2 for one thread.
class SolveWorkspace {
  public:
    ~SolveWorkspace() {
        cholmod_free_dense(&x, common.get());
        cholmod_free_dense(&y, common.get());
        cholmod_free_dense(&e, common.get());
    }
    CholmodCommon common;
    cholmod_dense* x = nullptr;
    cholmod_dense* y = nullptr;
    cholmod_dense* e = nullptr;
};

void validateInput(const TriMesh& mesh, const std::vector<BoneSegment>& bones,
                   const ClosestBones& closestBones, const BoneHeatOptions& options) {
    if (bones.empty()) {
        throw Error(MessageId::WeightsNeedBone);
    }
    if (std::none_of(bones.begin(), bones.end(), [](const auto& b) { return isFinite(b); })) {
        throw Error(MessageId::WeightsNeedFiniteBone);
    }
    for (const Vec3& p : mesh.vertices) {
        if (!p.allFinite()) {
            throw Error(MessageId::MeshVertexPositionNotFinite);
        }
    }
    for (const auto& face : mesh.faces) {
        for (int corner : face) {
            if (corner < 0 || corner >= mesh.vertexCount()) {
                throw Error(MessageId::MeshTriangleMissingVertex);
            }
        }
    }
    if (!closestBones.empty() && closestBones.size() != mesh.vertices.size()) {
        throw std::logic_error("The closest bones must be given for every vertex or for none.");
    }
    if (!(options.heatConstant > 0.0) || !std::isfinite(options.heatConstant)) {
        throw std::logic_error("The heat constant must be a positive number.");
    }
    if (!(options.taperEnd >= 0.0) || !(options.taperStart >= options.taperEnd) ||
        !(options.taperStart < 1.0)) {
        throw std::logic_error("The weight taper needs 0 <= end <= start < 1.");
    }
    if (options.threads < 1) {
        throw std::logic_error("The skin weight solver needs at least one thread.");
    }
}

}  // namespace

struct BoneHeatSolver::Impl {
    BoneHeatOptions options;
    std::vector<Vec3> positions;
    std::vector<BoneSegment> bones;
    std::vector<char> boneIsFinite;
    ClosestBones closest;
    int withoutVisible = 0;
    // Per vertex the diagonal heat term a_i = A_i H_i (1 for a vertex no
    // triangle uses, whose weight is then simply p_i).
    Eigen::VectorXd heat;
    Eigen::SparseMatrix<double> matrix;
    // With a mirror image (see BoneHeatSolver.h): each vertex's unknown (a
    // vertex and its image share one), their count, and R^T matrix R (upper
    // triangle stored). Empty orbit when the full system is solved.
    std::vector<int> orbit;
    int orbitCount = 0;
    Eigen::SparseMatrix<double> reducedMatrix;
    CholmodCommon common;
    cholmod_factor* factor = nullptr;
    // One bone: its heat is 1 at every vertex (BoneHeatSolver.h), nothing
    // is factored or solved, and the system is assembled only if asked for
    // (systemMatrix, rightHandSide), from the faces kept here.
    bool singleBone = false;
    std::vector<std::array<int, 3>> singleBoneFaces;
    std::once_flag assembled;

    ~Impl() {
        if (factor != nullptr) {
            cholmod_free_factor(&factor, common.get());
        }
    }

    int vertexCount() const { return static_cast<int>(positions.size()); }
    int boneCount() const { return static_cast<int>(bones.size()); }

    void findClosestBones(const TriMesh& mesh, const ClosestBones& given);
    // L + A H over `faces` (of `positions`).
    void assemble(const std::vector<std::array<int, 3>>& faces);
    // The system of a single bone, assembled on first use.
    void assembleSingleBone();
    void useMirror(const TriMesh& mesh, const std::vector<int>& mirror);
    void reduce();
    void factorize();
    Eigen::VectorXd rightHandSide(int bone) const;
    Eigen::VectorXd nearestBoneWeights(int bone) const;
    // Solves one bone into `out`; false if it failed (out then holds the
    // nearest-bone fallback).
    bool solve(int bone, SolveWorkspace& workspace, Eigen::Ref<Eigen::VectorXd> out) const;
    int closestBoneOf(int vertex) const;
};

void BoneHeatSolver::Impl::findClosestBones(const TriMesh& mesh, const ClosestBones& given) {
    closest.assign(positions.size(), {});
    std::vector<int> toTest;
    for (int v = 0; v < vertexCount(); ++v) {
        if (!given.empty()) {
            for (const auto& [bone, distance] : given[v]) {
                if (bone < 0 || bone >= boneCount()) {
                    throw std::logic_error("A closest bone refers to a bone that does not exist.");
                }
                if (boneIsFinite[bone] && std::isfinite(distance) && distance >= 0.0) {
                    closest[v].emplace_back(bone, distance);
                }
            }
        }
        if (closest[v].empty()) {
            toTest.push_back(v);
        }
    }
    if (toTest.empty()) {
        return;
    }
    // The paper's bottleneck (section 2.4): test only what the caller could
    // not fill, split over the threads.
    const BoneVisibility visibility(mesh);
    const std::vector<Vec3> normals = vertexNormals(mesh);
    const int total = static_cast<int>(toTest.size());
    std::vector<int> counts(parallelWorkers(total, options.threads), 0);
    parallelFor(total, options.threads, [&](int begin, int end, int worker) {
        const std::vector<int> part(toTest.begin() + begin, toTest.begin() + end);
        auto found = closestVisibleBones(mesh, normals, bones, visibility, part,
                                         options.tieTolerance, &counts[worker]);
        for (std::size_t i = 0; i < part.size(); ++i) {
            closest[part[i]] = std::move(found[i]);
        }
    });
    for (int count : counts) {
        withoutVisible += count;
    }
}

void BoneHeatSolver::Impl::assemble(const std::vector<std::array<int, 3>>& faces) {
    const int n = vertexCount();
    const int faceTotal = static_cast<int>(faces.size());
    Eigen::VectorXd area = Eigen::VectorXd::Zero(n);
    // Per vertex: how many usable triangles it has, and the uniform weights
    // of the edges of its unusable ones (used only if it has no other).
    std::vector<int> goodFaces(n, 0);
    std::vector<char> inAnyFace(n, 0);
    // Per usable face its corners' cot/2.
    std::vector<char> usable(faceTotal, 0);
    std::vector<double> halfCots(3 * static_cast<std::size_t>(faceTotal));
    std::vector<std::array<int, 3>> degenerate;
    for (int f = 0; f < faceTotal; ++f) {
        const auto& face = faces[f];
        for (int corner : face) {
            inAnyFace[corner] = 1;
        }
        const double doubleArea = usableDoubleArea(face, positions);
        if (doubleArea == 0.0) {
            degenerate.push_back(face);
            continue;
        }
        usable[f] = 1;
        for (int c = 0; c < 3; ++c) {
            const int i = face[c];
            const int j = face[(c + 1) % 3];
            const int k = face[(c + 2) % 3];
            ++goodFaces[i];
            area[i] += 0.5 * doubleArea;  // the one-ring area (see BoneHeatSolver.h)
            // The corner at i weighs the opposite edge (j, k) by cot/2.
            const Vec3 e1 = positions[j] - positions[i];
            const Vec3 e2 = positions[k] - positions[i];
            halfCots[3 * f + c] = 0.5 * e1.dot(e2) / doubleArea;
        }
    }
    // A vertex whose every triangle is degenerate (a junction patch can emit
    // such slivers) has no area and no angles: it takes the mean of its
    // neighbours (uniform weights on its edges) instead of being pinned.
    std::vector<std::array<int, 2>> orphanEdges;
    std::vector<double> orphanDegree(n, 0.0);
    for (const auto& face : degenerate) {
        for (int c = 0; c < 3; ++c) {
            const int a = face[c];
            const int b = face[(c + 1) % 3];
            if (a == b || (goodFaces[a] > 0 && goodFaces[b] > 0)) {
                continue;
            }
            orphanEdges.push_back({a, b});
            orphanDegree[a] += 1.0;
            orphanDegree[b] += 1.0;
        }
    }

    heat = Eigen::VectorXd::Zero(n);
    for (int v = 0; v < n; ++v) {
        if (!inAnyFace[v]) {
            heat[v] = 1.0;  // no triangle at all: w_v = p_v
        } else if (goodFaces[v] == 0) {
            // Keeps the system definite if a whole cluster is degenerate,
            // without pulling the vertex away from its neighbours' mean.
            heat[v] = kOrphanHeatPerEdge * std::max(orphanDegree[v], 1.0);
        } else if (!closest[v].empty()) {
            double d = closest[v].front().second;
            for (const auto& entry : closest[v]) {
                d = std::min(d, entry.second);
            }
            heat[v] = heatTerm(area[v], d, options);
        }
    }

    // L + A H in the order its terms were added as triplets: per usable
    // face and corner i the opposite edge (j, k) -cot/2 and j, k +cot/2 each,
    // then the orphans' edges, then each vertex's heat.
    upperFromTerms(
        n,
        [&](auto&& add) {
            for (int f = 0; f < faceTotal; ++f) {
                if (!usable[f]) {
                    continue;
                }
                const auto& face = faces[f];
                for (int c = 0; c < 3; ++c) {
                    const int j = face[(c + 1) % 3];
                    const int k = face[(c + 2) % 3];
                    const double halfCot = halfCots[3 * f + c];
                    add(std::min(j, k), std::max(j, k), -halfCot);
                    add(j, j, halfCot);
                    add(k, k, halfCot);
                }
            }
            for (const auto& [a, b] : orphanEdges) {
                add(std::min(a, b), std::max(a, b), -1.0);
                add(a, a, 1.0);
                add(b, b, 1.0);
            }
            for (int v = 0; v < n; ++v) {
                add(v, v, heat[v]);
            }
        },
        matrix);
}

void BoneHeatSolver::Impl::assembleSingleBone() {
    std::call_once(assembled, [&] { assemble(singleBoneFaces); });
}

void BoneHeatSolver::Impl::useMirror(const TriMesh& mesh, const std::vector<int>& mirror) {
    if (mirror.empty() || !mirrorFaceImages(mesh, mirror))
        return;
    for (int v = 0; v < vertexCount(); ++v)
        if (closest[v] != closest[mirror[v]])
            return;  // the heat or a right-hand side is not mirror-symmetric
    orbit.assign(positions.size(), -1);
    orbitCount = 0;
    for (int v = 0; v < vertexCount(); ++v)
        if (orbit[v] < 0) {
            orbit[v] = orbit[mirror[v]] = orbitCount;
            ++orbitCount;
        }
}

// R^T matrix R from the full matrix's upper triangle: entry (i, j) of the
// full matrix adds to (orbit i, orbit j); an off-diagonal entry joining a
// vertex to its own image adds twice (as (i, j) and (j, i)) to the diagonal.
void BoneHeatSolver::Impl::reduce() {
    upperFromTerms(
        orbitCount,
        [&](auto&& add) {
            for (int column = 0; column < matrix.outerSize(); ++column) {
                for (Eigen::SparseMatrix<double>::InnerIterator it(matrix, column); it; ++it) {
                    const int a = orbit[it.row()], b = orbit[it.col()];
                    if (a == b && it.row() != it.col()) {
                        add(a, a, 2.0 * it.value());
                    } else {
                        add(std::min(a, b), std::max(a, b), it.value());
                    }
                }
            }
        },
        reducedMatrix);
}

void BoneHeatSolver::Impl::factorize() {
    cholmod_common* c = common.get();
    // Simplicial LDL^T with AMD: meshes of a few thousand vertices factor in
    // milliseconds and single right-hand sides solve without BLAS.
    c->supernodal = CHOLMOD_SIMPLICIAL;
    c->nmethods = 1;
    c->method[0].ordering = CHOLMOD_AMD;
    const Eigen::SparseMatrix<double>& upper = orbit.empty() ? matrix : reducedMatrix;
    cholmod_sparse a = Eigen::viewAsCholmod(upper.selfadjointView<Eigen::Upper>());
    factor = cholmod_analyze(&a, c);
    if (factor == nullptr) {
        return;
    }
    const int ok = cholmod_factorize(&a, factor, c);
    if (!ok || c->status != CHOLMOD_OK || factor->minor != factor->n) {
        cholmod_free_factor(&factor, c);
        factor = nullptr;
    }
}

Eigen::VectorXd BoneHeatSolver::Impl::rightHandSide(int bone) const {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(vertexCount());
    for (int v = 0; v < vertexCount(); ++v) {
        const auto& list = closest[v];
        for (const auto& entry : list) {
            if (entry.first == bone) {
                // p_j(v) = 1/k when k bones tie for closest.
                rhs[v] += heat[v] / static_cast<double>(list.size());
            }
        }
    }
    return rhs;
}

// Inverse-square-distance share of the bone among the finite bones: the
// fallback when the heat equation cannot be solved for it.
Eigen::VectorXd BoneHeatSolver::Impl::nearestBoneWeights(int bone) const {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(vertexCount());
    if (!boneIsFinite[bone]) {
        return w;
    }
    std::vector<double> d(bones.size());
    for (int v = 0; v < vertexCount(); ++v) {
        double nearest = std::numeric_limits<double>::infinity();
        for (int b = 0; b < boneCount(); ++b) {
            d[b] = boneIsFinite[b] ? pointSegmentDistance(positions[v], bones[b])
                                   : std::numeric_limits<double>::infinity();
            nearest = std::min(nearest, d[b]);
        }
        double total = 0.0;
        double own = 0.0;
        for (int b = 0; b < boneCount(); ++b) {
            // (nearest / d)^2 avoids dividing by a zero distance.
            const double share =
                nearest == 0.0 ? (d[b] == 0.0 ? 1.0 : 0.0) : (nearest / d[b]) * (nearest / d[b]);
            total += share;
            if (b == bone) {
                own = share;
            }
        }
        w[v] = own / total;
    }
    return w;
}

bool BoneHeatSolver::Impl::solve(int bone, SolveWorkspace& workspace,
                                 Eigen::Ref<Eigen::VectorXd> out) const {
    if (singleBone) {
        out.setOnes();
        return true;
    }
    if (factor != nullptr && boneIsFinite[bone]) {
        Eigen::VectorXd rhs = rightHandSide(bone);
        if (!orbit.empty()) {
            Eigen::VectorXd summed = Eigen::VectorXd::Zero(orbitCount);  // R^T rhs
            for (int v = 0; v < vertexCount(); ++v)
                summed[orbit[v]] += rhs[v];
            rhs = std::move(summed);
        }
        cholmod_dense b = Eigen::viewAsCholmod(rhs);
        const int ok = cholmod_solve2(CHOLMOD_A, factor, &b, nullptr, &workspace.x, nullptr,
                                      &workspace.y, &workspace.e, workspace.common.get());
        if (ok && workspace.x != nullptr) {
            const auto* x = static_cast<const double*>(workspace.x->x);
            if (orbit.empty())
                out = Eigen::Map<const Eigen::VectorXd>(x, vertexCount());
            else
                for (int v = 0; v < vertexCount(); ++v)
                    out[v] = x[orbit[v]];  // w = R u
            if (out.allFinite()) {
                return true;
            }
        }
    }
    out = nearestBoneWeights(bone);
    return false;
}

int BoneHeatSolver::Impl::closestBoneOf(int vertex) const {
    if (!closest[vertex].empty()) {
        return std::min_element(closest[vertex].begin(), closest[vertex].end(),
                                [](const auto& a, const auto& b) { return a.second < b.second; })
            ->first;
    }
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int b = 0; b < boneCount(); ++b) {
        const double d = boneIsFinite[b] ? pointSegmentDistance(positions[vertex], bones[b])
                                         : std::numeric_limits<double>::infinity();
        if (best < 0 || d < bestDistance) {
            best = b;
            bestDistance = d;
        }
    }
    return best;
}

BoneHeatSolver::BoneHeatSolver(const TriMesh& mesh, const std::vector<BoneSegment>& bones,
                               const ClosestBones& closestBones, const BoneHeatOptions& options,
                               const std::vector<int>& mirror)
    : impl_(std::make_unique<Impl>()) {
    validateInput(mesh, bones, closestBones, options);
    impl_->options = options;
    impl_->positions = mesh.vertices;
    impl_->bones = bones;
    for (const auto& bone : bones) {
        impl_->boneIsFinite.push_back(isFinite(bone) ? 1 : 0);
    }
    impl_->findClosestBones(mesh, closestBones);
    impl_->singleBone = bones.size() == 1;  // finite (validateInput)
    if (impl_->singleBone) {
        impl_->singleBoneFaces = mesh.faces;
        return;
    }
    impl_->assemble(mesh.faces);
    impl_->useMirror(mesh, mirror);
    if (!impl_->orbit.empty())
        impl_->reduce();
    impl_->factorize();
}

BoneHeatSolver::~BoneHeatSolver() = default;
BoneHeatSolver::BoneHeatSolver(BoneHeatSolver&&) noexcept = default;
BoneHeatSolver& BoneHeatSolver::operator=(BoneHeatSolver&&) noexcept = default;

int BoneHeatSolver::vertexCount() const {
    return impl_->vertexCount();
}
int BoneHeatSolver::boneCount() const {
    return impl_->boneCount();
}
bool BoneHeatSolver::isFactorized() const {
    return impl_->factor != nullptr || impl_->singleBone;
}
bool BoneHeatSolver::solvesMirrorSymmetric() const {
    return !impl_->orbit.empty();
}
const ClosestBones& BoneHeatSolver::closestBones() const {
    return impl_->closest;
}
int BoneHeatSolver::verticesWithoutVisibleBone() const {
    return impl_->withoutVisible;
}
const Eigen::SparseMatrix<double>& BoneHeatSolver::systemMatrix() const {
    if (impl_->singleBone)
        impl_->assembleSingleBone();
    return impl_->matrix;
}

Eigen::VectorXd BoneHeatSolver::rightHandSide(int bone) const {
    if (bone < 0 || bone >= boneCount()) {
        throw std::logic_error("There is no bone with this index.");
    }
    if (impl_->singleBone)
        impl_->assembleSingleBone();
    return impl_->rightHandSide(bone);
}

Eigen::VectorXd BoneHeatSolver::solveBone(int bone) const {
    if (bone < 0 || bone >= boneCount()) {
        throw std::logic_error("There is no bone with this index.");
    }
    SolveWorkspace workspace;
    Eigen::VectorXd w(vertexCount());
    impl_->solve(bone, workspace, w);
    return w;
}

SkinWeights BoneHeatSolver::solveAll() const {
    const int n = vertexCount();
    const int boneTotal = boneCount();
    Eigen::MatrixXd solutions(n, boneTotal);
    std::vector<char> failed(boneTotal, 0);
    const int workers = parallelWorkers(boneTotal, impl_->options.threads);
    std::vector<std::unique_ptr<SolveWorkspace>> workspaces;
    for (int t = 0; t < workers; ++t) {
        workspaces.push_back(std::make_unique<SolveWorkspace>());
    }
    parallelFor(boneTotal, impl_->options.threads, [&](int begin, int end, int worker) {
        for (int bone = begin; bone < end; ++bone) {
            failed[bone] = impl_->solve(bone, *workspaces[worker], solutions.col(bone)) ? 0 : 1;
        }
    });

    // Pinocchio's post-processing with Blender's taper: negatives to 0, small
    // weights faded out, renormalise; an emptied vertex follows its closest bone.
    SkinWeights result;
    result.perVertex.resize(n);
    for (int v = 0; v < n; ++v) {
        auto& weights = result.perVertex[v];
        double total = 0.0;
        for (int b = 0; b < boneTotal; ++b) {
            const double w = taperedWeight(solutions(v, b), impl_->options);
            if (w > 0.0) {
                weights.emplace_back(b, w);
                total += w;
            }
        }
        if (weights.empty()) {
            weights.emplace_back(impl_->closestBoneOf(v), 1.0);
            continue;
        }
        for (auto& entry : weights) {
            entry.second /= total;
        }
    }

    for (int b = 0; b < boneTotal; ++b) {
        if (failed[b]) {
            result.failedBones.push_back(b);
        }
    }
    if (!isFactorized()) {
        result.warnings.push_back({MessageId::WeightsNotFactored, {}});
    } else if (!result.failedBones.empty()) {
        std::string bones;
        for (const int bone : result.failedBones)
            bones += (bones.empty() ? "" : ", ") + std::to_string(bone);
        result.warnings.push_back({result.failedBones.size() > 1 ? MessageId::WeightsBonesUnsolved
                                                                 : MessageId::WeightsBoneUnsolved,
                                   {bones}});
    }
    if (impl_->withoutVisible > 0)
        result.warnings.push_back(
            {MessageId::WeightsVerticesSeeNoBone, {messageArgument(impl_->withoutVisible)}});
    return result;
}

SkinWeights computeBoneHeatWeights(const TriMesh& mesh, const std::vector<BoneSegment>& bones,
                                   const ClosestBones& closestBones, const BoneHeatOptions& options,
                                   const std::vector<int>& mirror) {
    return BoneHeatSolver(mesh, bones, closestBones, options, mirror).solveAll();
}

}  // namespace rigmesh
