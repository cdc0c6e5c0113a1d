// A pose of a skeleton (paper section 3, "posing with FK/IK"): one rotation
// per bone, as Blender's pose bones have, keyed by stable JointId so that a
// pose survives skeleton edits that keep the joint. A missing joint means the
// identity (rest) rotation.
//
// Per-bone rotations: the skeleton is a tree, so every joint but the root
// ends exactly one bone (the bone from its parent to it). A non-root joint's
// rotation is the rotation of that bone about the bone's head (the parent
// joint), relative to the parent bone; it carries the bone and everything
// below it, and nothing else: the bones leaving one junction turn
// independently. The root joint's rotation turns the whole skeleton about
// the root, and rootTranslation then moves it. The root of an attached chain
// (Skeleton.h: the head of disconnected bones) ends no bone: its rotation
// turns its chain about it, as the root's turns the skeleton; the bones
// leaving it then turn relative to that.
//
// Frames: at rest every bone frame has the world axes, so identity
// everywhere is the rest pose, and a bone's world rotation is its parent
// bone's world rotation times its own rotation (root bones: the root's
// rotation times their own).
//
// Documents and recipes of format version 1 stored one rotation per joint
// that turned every bone leaving the joint; LegacyPose.h converts them
// exactly.
#pragma once

#include <map>

#include <Eigen/Geometry>

#include "base/Types.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct Pose {
    // Per-bone rotations (unit quaternions), keyed by the joint each bone
    // ends at (the root: the whole skeleton); ordered by id for
    // deterministic iteration (clip interpolation, output).
    std::map<JointId, Eigen::Quaterniond> rotations;
    // Moves the root joint (and so the whole skeleton) in world space.
    Vec3 rootTranslation = Vec3::Zero();

    // The rotation of the bone ending at `joint` (of the whole skeleton for
    // the root); identity when it is not in the map.
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
