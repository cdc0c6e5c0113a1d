// A pose of a skeleton (paper section 3, "posing with FK/IK"): one rotation
// per joint, local to its parent's frame, keyed by stable JointId so that a
// pose survives skeleton edits that keep the joint. A missing joint means the
// identity (rest) rotation. A joint's rotation turns its whole subtree (every
// bone below it, including the bones starting at it) about the joint.
//
// Frames: at rest every joint frame has the world axes, so a local rotation
// of identity everywhere is the rest pose, and a joint's world rotation is
// its parent's world rotation times its own local rotation.
#pragma once

#include <map>

#include <Eigen/Geometry>

#include "base/Types.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct Pose {
    // Local rotations (unit quaternions); ordered by id for deterministic
    // iteration (clip interpolation, output).
    std::map<JointId, Eigen::Quaterniond> rotations;
    // Moves the root joint (and so the whole skeleton) in world space.
    Vec3 rootTranslation = Vec3::Zero();

    // The local rotation of `joint`; identity when it is not in the map.
    Eigen::Quaterniond rotation(JointId joint) const {
        const auto it = rotations.find(joint);
        return it == rotations.end() ? Eigen::Quaterniond::Identity() : it->second;
    }
    void setRotation(JointId joint, const Eigen::Quaterniond& q) { rotations[joint] = q; }
    // True if every rotation is finite and non-zero and the translation finite.
    bool isFinite() const;
};

// Every joint of `skeleton` at the identity rotation, no root translation.
Pose restPose(const Skeleton& skeleton);

}  // namespace rigmesh
