// Forward kinematics (paper section 3: parts are posed by FK/IK on their
// skeleton). Every bone turns about its head (the joint nearer the root) by
// its own rotation (Pose.h), composed parent bone first. Per joint j, F_j is
// the transform of the bone ending at j (for the root: of the whole
// skeleton):
//     F_root = translate(rootTranslation) * rotate(r_root about rest_root)
//     F_j    = F_parent(j) * rotate(r_j about rest_parent(j))
// and for the root j of an attached chain (Skeleton.h: a disconnected bone's
// head, whose parent joint is the tail of the bone it hangs from)
//     F_j    = F_parent(j) * rotate(r_j about rest_j),
// so the chain's head moves with its parent bone's frame, as Blender moves a
// disconnected child, and r_j turns the whole chain about its head.
// F_j maps rest space to posed space for everything rigidly attached to the
// bone ending at j: it is the bone's world frame times the inverse of its
// rest frame (rest frames are translations to the rest positions, world
// axes), i.e. exactly the bone's skinning transform. Bone lengths are
// preserved by construction (rigid transforms only); the rest pose gives
// identity transforms exactly, since a rotation about a point by the
// identity quaternion has a zero translation with no rounding.
#pragma once

#include <vector>

#include "pose/Pose.h"
#include "pose/PoseHierarchy.h"
#include "pose/RigidTransform.h"

namespace rigmesh {

struct PosedSkeleton {
    // Per joint index (skeleton.joints() order): F_j above, rest space ->
    // posed space for the bone ending at the joint (the root: the whole
    // skeleton's transform). Its rotation is that bone's world rotation.
    // Joints the root cannot reach keep the identity.
    std::vector<RigidTransform> jointTransforms;
    // Per joint index: posed world position.
    std::vector<Vec3> jointPositions;
    // Per bone index (skeleton.bones() order): the bone's transform, i.e.
    // jointTransforms of its tail (the joint farther from the root).
    std::vector<RigidTransform> boneTransforms;
};

// Throws Error if a rotation in the pose is not finite or zero, or the root
// translation is not finite. Rotations are normalised before use.
PosedSkeleton forwardKinematics(const PoseHierarchy& hierarchy, const Pose& pose);
PosedSkeleton forwardKinematics(const Skeleton& skeleton, const Pose& pose);

}  // namespace rigmesh
