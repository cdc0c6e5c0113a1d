// Joins the skeletons of two parts being merged (paper 3.2, Fig. 8):
//  - snap: the dragged part translates so that its chosen joint lands on the
//    target's chosen joint, and the two joints become one;
//  - split: a new joint goes on the target's bone at the point's projection,
//    then the dragged joint snaps to it;
//  - connect: nothing moves; a new bone joins the two chosen joints.
// The target keeps its joint and bone ids; the dragged part's get new ones.
#pragma once

#include <map>
#include <optional>

#include "rig/Skeleton.h"

namespace rigmesh {

enum class MergeMode { Snap, Split, Connect };

struct SkeletonJoinRequest {
    MergeMode mode = MergeMode::Snap;
    JointId draggedJoint = kNoJoint;
    JointId targetJoint = kNoJoint;  // snap and connect
    BoneId targetBone = 0;           // split: the bone to split ...
    Vec3 splitPoint = Vec3::Zero();  // ... at this point's projection on it
};

struct SkeletonJoin {
    Skeleton skeleton;                         // one tree, root not yet chosen
    Vec3 draggedTranslation = Vec3::Zero();    // to apply to the dragged part first
    std::map<JointId, JointId> draggedJoints;  // dragged id -> merged id
    std::map<BoneId, BoneId> draggedBones;     // dragged id -> merged id
    JointId meetingJoint = kNoJoint;           // where the skeletons meet (target side)
    std::optional<BoneId> splitTail;           // split: the new bone from the new joint on
    std::optional<BoneId> connectingBone;      // connect: the new bone
};

// Throws Error with a message for the user on unknown joints or bones, or
// joints to connect closer than `minimumBone` (rig/ShortBones.h). A split
// point within 5% of the bone or `minimumBone` of one of its joints snaps to
// that joint, so no bone shorter than that is made.
SkeletonJoin joinSkeletons(const Skeleton& target, const Skeleton& dragged,
                           const SkeletonJoinRequest& request, double minimumBone = 0.0);

}  // namespace rigmesh
