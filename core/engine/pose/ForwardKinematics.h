// Forward kinematics (paper section 3: parts are posed by FK/IK on their
// skeleton). Each joint's local rotation turns its subtree about the joint,
// composed parent first:
//     T_root  = translate(rootTranslation) * rotate(q_root about rest_root)
//     T_child = T_parent * rotate(q_child about rest_child)
// T_j maps rest space to posed space for everything rigidly attached to joint
// j's frame: it is the joint's world frame times the inverse of its rest frame
// (rest frames are translations to the rest positions, world axes), i.e.
// exactly the per-bone skinning transform. Bone lengths are preserved by
// construction (rigid transforms only); the rest pose gives identity
// transforms exactly, since a rotation about a point by the identity
// quaternion has a zero translation with no rounding.
#pragma once

#include <vector>

#include "pose/Pose.h"
#include "pose/PoseHierarchy.h"
#include "pose/RigidTransform.h"

namespace rigmesh {

struct PosedSkeleton {
    // Per joint index (skeleton.joints() order): rest space -> posed space.
    // Its rotation is the joint's world rotation. Joints the root cannot
    // reach keep the identity.
    std::vector<RigidTransform> jointTransforms;
    // Per joint index: posed world position.
    std::vector<Vec3> jointPositions;
    // Per bone index (skeleton.bones() order): the transform of the bone's
    // joint nearer the root, i.e. world * inverse rest of the bone.
    std::vector<RigidTransform> boneTransforms;
};

// Throws Error if a rotation in the pose is not finite or zero, or the root
// translation is not finite. Rotations are normalised before use.
PosedSkeleton forwardKinematics(const PoseHierarchy& hierarchy, const Pose& pose);
PosedSkeleton forwardKinematics(const Skeleton& skeleton, const Pose& pose);

}  // namespace rigmesh
