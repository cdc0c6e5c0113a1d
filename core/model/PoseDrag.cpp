#include "model/PoseDrag.h"

#include <vector>

#include "base/Error.h"

namespace rigmesh::model {

IkOptions poseToolIkOptions(IkReach reach) {
    IkOptions options;
    options.softReach = 0.05;
    options.stopAtJunctions = reach == IkReach::Limb;
    return options;
}

IkResult dragPartJoint(const PartNode& node, JointId joint, const Vec3& target, IkReach reach) {
    if (!node.part)
        throw Error(MessageId::PoseNoSkeleton);
    const std::vector<JointId> pinned(node.pinnedJoints.begin(), node.pinnedJoints.end());
    return dragJoint(node.part->skeleton, node.pose, joint, target, pinned,
                     poseToolIkOptions(reach));
}

}  // namespace rigmesh::model
