#include "pose/Skinning.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "base/ParallelFor.h"
#include "mesh/VertexNormals.h"
#include "pose/ForwardKinematics.h"
#include "pose/SkinningKernel.h"

namespace rigmesh {

namespace {

// The per-bone data of SkinningTransforms by slot, as the kernels read it.
struct SlotTable {
    const SkinningTransforms& t;
    const double* real(std::size_t slot) const { return t.dualQuaternionReal(slot).data(); }
    const double* dual(std::size_t slot) const { return t.dualQuaternionDual(slot).data(); }
    const double* matrix(std::size_t slot) const { return t.rotationMatrix(slot).data(); }
    const double* translation(std::size_t slot) const { return t.translation(slot).data(); }
    bool identity(std::size_t slot) const { return t.isIdentity(slot); }
};

// The weight lists by slot as the kernels read them. With `check`, every
// bone is checked against the transforms' skeleton before its slot is read.
struct ListSource {
    const WeightsById& lists;
    const SkinningTransforms* check;

    bool empty(int v) const { return lists[v].empty(); }
    // The first of the largest weights, as std::max_element finds it.
    std::size_t pivot(int v) const {
        const auto& influences = lists[v];
        if (check)
            for (const auto& [bone, weight] : influences)
                skinning::checkBone(*check, bone);
        std::size_t best = 0;
        for (std::size_t k = 1; k < influences.size(); ++k)
            if (influences[best].second < influences[k].second)
                best = k;
        return influences[best].first;
    }
    template <class F>
    void forEach(int v, F&& f) const {
        for (const auto& [bone, weight] : lists[v]) {
            if (check)
                skinning::checkBone(*check, bone);
            f(static_cast<std::size_t>(bone), weight);
        }
    }
};

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
    skinning::checkInput(weights.size(), restPositions.size(), restNormals.size(), options.threads);
    const int count = static_cast<int>(restPositions.size());
    const bool withNormals = !restNormals.empty();
    // Ids far beyond the bone count: weights moved onto the slots once (and
    // checked there); else each vertex's bones are checked as it is skinned,
    // which saves a second walk through the lists.
    WeightsById bySlot;
    if (!transforms.slotsAreIds()) {
        bySlot = weights;
        for (auto& influences : bySlot)
            for (auto& [bone, weight] : influences) {
                skinning::checkBone(transforms, bone);
                bone = static_cast<BoneId>(transforms.slotOf(bone));
            }
    }
    const WeightsById& slotted = transforms.slotsAreIds() ? weights : bySlot;

    SkinnedVertices out;
    out.positions.resize(count);
    if (withNormals)
        out.normals.resize(count);

    const SlotTable table{transforms};
    const ListSource source{slotted, transforms.slotsAreIds() ? &transforms : nullptr};
    const auto run = [&](int begin, int end) {
        skinning::skinRange(table, source, options.method, begin, end, restPositions, restNormals,
                            out);
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
