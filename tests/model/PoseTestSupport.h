// Pose helpers of the model tests: realistic poses from IK drags.
#pragma once

#include <algorithm>
#include <vector>

#include "model/PartNode.h"
#include "pose/InverseKinematics.h"

namespace rigmesh::model::test {

// The non-root joints of a skeleton with one bone (the ends), in id order.
inline std::vector<JointId> endJoints(const Skeleton& skeleton) {
    std::vector<JointId> out;
    for (const Joint& joint : skeleton.joints()) {
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) == 1)
            out.push_back(joint.id);
    }
    std::sort(out.begin(), out.end());
    return out;
}

// The node's pose after dragging `joint` to its rest position + `offset`
// (IK from the node's current pose, keeping its pinned joints).
inline rigmesh::Pose dragged(const PartNode& node, JointId joint, const Vec3& offset) {
    const Skeleton& skeleton = node.part->skeleton;
    const std::vector<JointId> pinned(node.pinnedJoints.begin(), node.pinnedJoints.end());
    return dragJoint(skeleton, node.pose, joint, skeleton.joint(joint).position + offset, pinned)
        .pose;
}

}  // namespace rigmesh::model::test
