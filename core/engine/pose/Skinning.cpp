#include "pose/Skinning.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "base/ParallelFor.h"
#include "pose/ForwardKinematics.h"
#include "pose/VertexNormals.h"

namespace rigmesh {

namespace {

// A vertex's weights by slot of the transforms (the bone ids themselves,
// but for ids far beyond the bone count).
using Influences = std::vector<std::pair<BoneId, double>>;

bool allIdentity(const Influences& influences, const SkinningTransforms& t) {
    for (const auto& [bone, weight] : influences) {
        if (!t.isIdentity(bone))
            return false;
    }
    return true;
}

// m * x written out: Eigen's 3x3 product is an out-of-line call per vertex
// in the dev build (perf on bench_pose: 13% of DQS at 100k vertices).
inline Vec3 times(const Eigen::Matrix3d& m, const Vec3& x) {
    return Vec3(m(0, 0) * x[0] + m(0, 1) * x[1] + m(0, 2) * x[2],
                m(1, 0) * x[0] + m(1, 1) * x[1] + m(1, 2) * x[2],
                m(2, 0) * x[0] + m(2, 1) * x[1] + m(2, 2) * x[2]);
}

inline Vec3 normalisedOr(const Vec3& v, const Vec3& fallback) {
    const double length = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return length > 0 ? Vec3(v[0] / length, v[1] / length, v[2] / length) : fallback;
}

void linearBlend(const Influences& influences, const SkinningTransforms& t, const Vec3& x,
                 const Vec3* n, Vec3& xOut, Vec3* nOut) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
    Vec3 translation = Vec3::Zero();
    for (const auto& [bone, weight] : influences) {
        m.noalias() += weight * t.rotationMatrix(bone);
        translation.noalias() += weight * t.translation(bone);
    }
    xOut = times(m, x) + translation;
    if (n)
        *nOut = normalisedOr(times(m, *n), *n);
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
    xOut = times(r, x) + translation;
    if (n)
        *nOut = normalisedOr(times(r, *n), *n);
}

}  // namespace

SkinningTransforms::SkinningTransforms(const Skeleton& skeleton,
                                       const std::vector<RigidTransform>& boneTransforms)
    : positions_(skeleton), slotsAreIds_(positions_.coversAllInArray()) {
    if (static_cast<int>(boneTransforms.size()) != skeleton.boneCount())
        throw std::logic_error(
            "Skinning needs one transform per bone: " + std::to_string(boneTransforms.size()) +
            " for " + std::to_string(skeleton.boneCount()) + " bones.");
    const std::size_t slots = slotsAreIds_ ? positions_.arraySize() : boneTransforms.size();
    matrices_.assign(slots, Eigen::Matrix3d::Identity());
    translations_.assign(slots, Vec3::Zero());
    real_.assign(slots, Eigen::Vector4d(0, 0, 0, 1));
    dual_.assign(slots, Eigen::Vector4d::Zero());
    identity_.assign(slots, 1);  // slots of ids the skeleton lacks: never read
    for (int b = 0; b < skeleton.boneCount(); ++b) {
        const std::size_t slot = slotOf(skeleton.bones()[b].id);
        const RigidTransform& transform = boneTransforms[b];
        const Eigen::Quaterniond q = transform.rotation.normalized();
        const Vec3& tr = transform.translation;
        matrices_[slot] = q.toRotationMatrix();
        translations_[slot] = tr;
        real_[slot] = q.coeffs();
        // Dual part 0.5 * (0, t) * q (Kavan et al. 2008, section 2).
        const Vec3 dv = 0.5 * (q.w() * tr + tr.cross(q.vec()));
        const double dw = -0.5 * tr.dot(q.vec());
        dual_[slot] = Eigen::Vector4d(dv.x(), dv.y(), dv.z(), dw);
        identity_[slot] = transform.isIdentity() ? 1 : 0;
    }
}

SkinnedVertices skinVertices(const std::vector<Vec3>& restPositions,
                             const std::vector<Vec3>& restNormals, const WeightsById& weights,
                             const SkinningTransforms& transforms, const SkinningOptions& options) {
    const int count = static_cast<int>(restPositions.size());
    if (static_cast<int>(weights.size()) != count)
        throw std::logic_error(
            "Skinning needs one weight list per vertex: " + std::to_string(weights.size()) +
            " lists for " + std::to_string(count) + " vertices.");
    const bool withNormals = !restNormals.empty();
    if (withNormals && static_cast<int>(restNormals.size()) != count)
        throw std::logic_error("Skinning needs one rest normal per vertex or none.");
    if (options.threads < 1)
        throw std::logic_error("Skinning needs at least one thread.");
    for (const auto& influences : weights) {
        for (const auto& [bone, weight] : influences) {
            if (!transforms.hasBone(bone))
                throw std::logic_error("A skin weight refers to bone " + std::to_string(bone) +
                                       ", which the posed skeleton does not have.");
        }
    }
    // Ids far beyond the bone count: weights moved onto the slots once.
    WeightsById bySlot;
    if (!transforms.slotsAreIds()) {
        bySlot = weights;
        for (auto& influences : bySlot)
            for (auto& [bone, weight] : influences)
                bone = static_cast<BoneId>(transforms.slotOf(bone));
    }
    const WeightsById& slotted = transforms.slotsAreIds() ? weights : bySlot;

    SkinnedVertices out;
    out.positions.resize(count);
    if (withNormals)
        out.normals.resize(count);
    const bool dqs = options.method == SkinningMethod::DualQuaternion;

    const auto run = [&](int begin, int end) {
        for (int v = begin; v < end; ++v) {
            const Influences& influences = slotted[v];
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
