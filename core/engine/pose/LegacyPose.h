// Poses of format version 1 (documents and recipes written before per-bone
// rotations): one rotation q_j per joint, turning every bone leaving j about
// j. The per-bone pose with the same bone transforms (Pose.h) gives each
// non-root joint j its parent's old rotation and the root the identity:
//     r_root = identity,   r_j = q_parent(j)
// The root's old rotation thus moves onto the bones leaving the root, and
// forward kinematics composes the very same products as before, so every
// bone transform, and every skinned vertex, comes out bit for bit as it
// did. A rotation of a leaf joint turned nothing and is dropped.
#pragma once

#include <map>

#include "pose/Clip.h"
#include "pose/Pose.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh {

// The per-bone pose of a version 1 pose. Joints the skeleton lacks or the
// root cannot reach are dropped.
Pose poseFromJointRotations(const PoseHierarchy& hierarchy, const Pose& legacy);
// The clip with every key converted; settings and name kept. Interpolation
// is per joint, so the converted clip evaluates at every time to the
// conversion of the old clip's pose.
Clip clipFromJointRotations(const PoseHierarchy& hierarchy, const Clip& legacy);
// Sets version 1 rotations of some joints in `pose` (a recipe's "pose" step
// without "complete"): the bones leaving each listed joint get its rotation.
// Exact when `pose` is itself the conversion of a version 1 pose. Throws
// Error on an unknown joint.
void setJointRotations(const PoseHierarchy& hierarchy,
                       const std::map<JointId, Eigen::Quaterniond>& jointRotations, Pose& pose);

}  // namespace rigmesh
