#include "model/PoseDrag.h"

#include <vector>

#include "base/Error.h"

namespace rigmesh::model {

IkOptions poseToolIkOptions() {
    IkOptions options;
    options.softReach = 0.05;
    return options;
}

IkResult dragPartJoint(const PartNode& node, JointId joint, const Vec3& target) {
    if (!node.part)
        throw Error("The part has no skeleton to pose.");
    const std::vector<JointId> pinned(node.pinnedJoints.begin(), node.pinnedJoints.end());
    return dragJoint(node.part->skeleton, node.pose, joint, target, pinned, poseToolIkOptions());
}

}  // namespace rigmesh::model
