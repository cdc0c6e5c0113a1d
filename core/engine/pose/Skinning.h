// Skinning a part's surface to a pose (paper section 3: posed parts deform
// with dual-quaternion skinning [Kavan et al. 2008]). Both methods read the
// part's sparse weights keyed by bone id (Part::weights.perVertex); the
// per-bone data is found through a dense id -> position table:
//   - linear blend skinning (LBS): x' = sum_b w_b (R_b x + t_b), normals by
//     the blended matrix sum_b w_b R_b, renormalised;
//   - dual quaternion skinning (DQS, Kavan et al. 2008): the unit dual
//     quaternions of the bone transforms are blended and normalised, which
//     gives a rigid transform per vertex and avoids LBS's volume loss (the
//     "candy wrapper") under twist; normals are rotated by the blended
//     rotation. Before blending, every bone's dual quaternion is flipped into
//     the hemisphere of the vertex's dominant bone (the antipodal fix, Kavan
//     et al. 2008 section 4): q and -q are the same transform but would
//     cancel in the sum.
// The per-bone transforms (world * inverse rest, i.e. FK's bone transforms)
// are precomputed once per pose. Vertices run on `threads` std::threads over
// contiguous ranges; each vertex is computed alone, so the output does not
// depend on the thread count. A vertex whose bones all have exactly the
// identity transform (all of them in the rest pose) is copied unchanged, so
// the rest pose returns the rest mesh bit for bit.
#pragma once

#include <vector>

#include <Eigen/Core>

#include "part/Part.h"
#include "pose/Pose.h"
#include "pose/RigidTransform.h"

namespace rigmesh {

enum class SkinningMethod { LinearBlend, DualQuaternion };

struct SkinningOptions {
    SkinningMethod method = SkinningMethod::DualQuaternion;  // the paper's choice
    int threads = 2;                                         // >= 1; capped by the vertex count
};

// Per-bone data derived once per pose from the bone transforms, stored in
// slots: at the bone's id (so skinning reads weights keyed by id with no
// lookup), or, for ids far beyond the bone count (a hand-edited file), at its
// position in skeleton.bones().
class SkinningTransforms {
  public:
    // `boneTransforms` in skeleton.bones() order (FK's PosedSkeleton). Throws
    // Error if their number differs from the skeleton's bones.
    SkinningTransforms(const Skeleton& skeleton, const std::vector<RigidTransform>& boneTransforms);

    bool hasBone(BoneId id) const { return positions_[id] >= 0; }
    // Whether slots are bone ids; else slotOf() maps them.
    bool slotsAreIds() const { return slotsAreIds_; }
    // The slot of a bone the skeleton has.
    std::size_t slotOf(BoneId id) const {
        return slotsAreIds_ ? id : static_cast<std::size_t>(positions_[id]);
    }
    const Eigen::Matrix3d& rotationMatrix(std::size_t slot) const { return matrices_[slot]; }
    const Vec3& translation(std::size_t slot) const { return translations_[slot]; }
    // The unit dual quaternion (real, dual) as (x, y, z, w) coefficients.
    const Eigen::Vector4d& dualQuaternionReal(std::size_t slot) const { return real_[slot]; }
    const Eigen::Vector4d& dualQuaternionDual(std::size_t slot) const { return dual_[slot]; }
    bool isIdentity(std::size_t slot) const { return identity_[slot] != 0; }

  private:
    BoneIndexTable positions_;
    bool slotsAreIds_ = true;
    std::vector<Eigen::Matrix3d> matrices_;
    std::vector<Vec3> translations_;
    std::vector<Eigen::Vector4d> real_, dual_;
    std::vector<char> identity_;
};

struct SkinnedVertices {
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;  // empty when no rest normals were given
};

// `weights`: per rest position, (bone id, weight). Throws Error if the
// weights do not have one list per rest position, refer to a bone the
// transforms' skeleton does not have, or `restNormals` is neither empty nor
// one per position, or options.threads < 1.
SkinnedVertices skinVertices(const std::vector<Vec3>& restPositions,
                             const std::vector<Vec3>& restNormals, const WeightsById& weights,
                             const SkinningTransforms& transforms,
                             const SkinningOptions& options = {});

struct PosedMesh {
    TriMesh mesh;               // the part's faces, skinned positions
    std::vector<Vec3> normals;  // skinned rest vertex normals
};

// FK + skinning of a whole part (convenience; recomputes the rest normals).
PosedMesh posePart(const Part& part, const Pose& pose, const SkinningOptions& options = {});

}  // namespace rigmesh
