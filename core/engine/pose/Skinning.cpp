#include "pose/Skinning.h"

#include <algorithm>
#include <string>

#include "base/Error.h"
#include "base/ParallelFor.h"
#include "pose/ForwardKinematics.h"
#include "pose/VertexNormals.h"

namespace rigmesh {

namespace {

// A vertex's weights by bone position in the transforms (the ids looked up
// once per vertex, into a small buffer that each thread reuses).
using Influences = std::vector<std::pair<int, double>>;

void lookUp(const std::vector<std::pair<BoneId, double>>& byId, const SkinningTransforms& t,
            Influences& out) {
    out.clear();
    for (const auto& [bone, weight] : byId)
        out.emplace_back(t.positionOf(bone), weight);
}

bool allIdentity(const Influences& influences, const SkinningTransforms& t) {
    for (const auto& [bone, weight] : influences) {
        if (!t.isIdentity(bone))
            return false;
    }
    return true;
}

Vec3 normalisedOr(const Vec3& v, const Vec3& fallback) {
    const double length = v.norm();
    return length > 0 ? Vec3(v / length) : fallback;
}

void linearBlend(const Influences& influences, const SkinningTransforms& t, const Vec3& x,
                 const Vec3* n, Vec3& xOut, Vec3* nOut) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    Vec3 translation = Vec3::Zero();
    for (const auto& [bone, weight] : influences) {
        m.noalias() += weight * t.rotationMatrix(bone);
        translation.noalias() += weight * t.translation(bone);
    }
    xOut = m * x + translation;
    if (n)
        *nOut = normalisedOr(m * *n, *n);
}

void dualQuaternionBlend(const Influences& influences, const SkinningTransforms& t, const Vec3& x,
                         const Vec3* n, Vec3& xOut, Vec3* nOut) {
    // The dominant bone's hemisphere (Kavan et al. 2008, section 4).
    const auto dominant =
        std::max_element(influences.begin(), influences.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    const Eigen::Vector4d& pivot = t.dualQuaternionReal(dominant->first);
    Eigen::Vector4d real = Eigen::Vector4d::Zero();
    Eigen::Vector4d dual = Eigen::Vector4d::Zero();
    for (const auto& [bone, weight] : influences) {
        const Eigen::Vector4d& r = t.dualQuaternionReal(bone);
        const double w = r.dot(pivot) < 0 ? -weight : weight;
        real.noalias() += w * r;
        dual.noalias() += w * t.dualQuaternionDual(bone);
    }
    // Normalise by the real part's norm (DLB, Kavan et al. 2008 section 3.4).
    const double norm = real.norm();
    if (!(norm > 0)) {
        xOut = x;
        if (n)
            *nOut = *n;
        return;
    }
    real /= norm;
    dual /= norm;
    const Eigen::Quaterniond q(real[3], real[0], real[1], real[2]);
    const Vec3 rv = real.head<3>(), dv = dual.head<3>();
    // Translation of a unit dual quaternion: 2 * dual * conj(real), written
    // out so that a non-orthogonal blended dual part is projected away.
    const Vec3 translation = 2.0 * (real[3] * dv - dual[3] * rv + rv.cross(dv));
    const Eigen::Matrix3d r = q.toRotationMatrix();
    xOut = r * x + translation;
    if (n)
        *nOut = normalisedOr(r * *n, *n);
}

}  // namespace

SkinningTransforms::SkinningTransforms(const Skeleton& skeleton,
                                       const std::vector<RigidTransform>& boneTransforms)
    : positions_(skeleton) {
    if (static_cast<int>(boneTransforms.size()) != skeleton.boneCount())
        throw Error(
            "Skinning needs one transform per bone: " + std::to_string(boneTransforms.size()) +
            " for " + std::to_string(skeleton.boneCount()) + " bones.");
    const std::size_t b = boneTransforms.size();
    matrices_.reserve(b);
    translations_.reserve(b);
    real_.reserve(b);
    dual_.reserve(b);
    identity_.reserve(b);
    for (const RigidTransform& transform : boneTransforms) {
        const Eigen::Quaterniond q = transform.rotation.normalized();
        const Vec3& tr = transform.translation;
        matrices_.push_back(q.toRotationMatrix());
        translations_.push_back(tr);
        real_.push_back(q.coeffs());
        // Dual part 0.5 * (0, t) * q (Kavan et al. 2008, section 2).
        const Vec3 dv = 0.5 * (q.w() * tr + tr.cross(q.vec()));
        const double dw = -0.5 * tr.dot(q.vec());
        dual_.push_back(Eigen::Vector4d(dv.x(), dv.y(), dv.z(), dw));
        identity_.push_back(transform.isIdentity() ? 1 : 0);
    }
}

SkinnedVertices skinVertices(const std::vector<Vec3>& restPositions,
                             const std::vector<Vec3>& restNormals, const WeightsById& weights,
                             const SkinningTransforms& transforms, const SkinningOptions& options) {
    const int count = static_cast<int>(restPositions.size());
    if (static_cast<int>(weights.size()) != count)
        throw Error("Skinning needs one weight list per vertex: " + std::to_string(weights.size()) +
                    " lists for " + std::to_string(count) + " vertices.");
    const bool withNormals = !restNormals.empty();
    if (withNormals && static_cast<int>(restNormals.size()) != count)
        throw Error("Skinning needs one rest normal per vertex or none.");
    if (options.threads < 1)
        throw Error("Skinning needs at least one thread.");
    for (const auto& influences : weights) {
        for (const auto& [bone, weight] : influences) {
            if (transforms.positionOf(bone) < 0)
                throw Error("A skin weight refers to bone " + std::to_string(bone) +
                            ", which the posed skeleton does not have.");
        }
    }

    SkinnedVertices out;
    out.positions.resize(count);
    if (withNormals)
        out.normals.resize(count);
    const bool dqs = options.method == SkinningMethod::DualQuaternion;

    const auto run = [&](int begin, int end) {
        Influences influences;
        for (int v = begin; v < end; ++v) {
            lookUp(weights[v], transforms, influences);
            const Vec3* n = withNormals ? &restNormals[v] : nullptr;
            Vec3* nOut = withNormals ? &out.normals[v] : nullptr;
            if (influences.empty() || allIdentity(influences, transforms)) {
                out.positions[v] = restPositions[v];
                if (n)
                    *nOut = *n;
            } else if (dqs) {
                dualQuaternionBlend(influences, transforms, restPositions[v], n, out.positions[v],
                                    nOut);
            } else {
                linearBlend(influences, transforms, restPositions[v], n, out.positions[v], nOut);
            }
        }
    };

    // Contiguous vertex ranges, one per thread: the split depends on the
    // counts only, so the output does not depend on timing.
    parallelFor(count, options.threads, [&](int begin, int end, int) { run(begin, end); });
    return out;
}

PosedMesh posePart(const Part& part, const Pose& pose, const SkinningOptions& options) {
    const PosedSkeleton posed = forwardKinematics(part.skeleton, pose);
    SkinnedVertices skinned =
        skinVertices(part.mesh.vertices, vertexNormals(part.mesh), part.weights.perVertex,
                     SkinningTransforms(part.skeleton, posed.boneTransforms), options);
    PosedMesh result;
    result.mesh.faces = part.mesh.faces;
    result.mesh.vertices = std::move(skinned.positions);
    result.normals = std::move(skinned.normals);
    return result;
}

}  // namespace rigmesh
