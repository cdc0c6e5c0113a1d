#include "io/ExportRig.h"

#include <cctype>
#include <deque>

#include "base/Error.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh {
namespace {

// The shortest rotation taking `axis` onto `along` (no roll). Opposite
// vectors turn half a turn about an axis perpendicular to both.
Eigen::Quaterniond boneFrame(const Vec3& axis, const Vec3& along) {
    if (!(along.norm() > 0))
        return Eigen::Quaterniond::Identity();
    const Vec3 direction = along.normalized();
    if (axis.dot(direction) < -1.0 + 1e-12) {
        const Vec3 turn = axis.unitOrthogonal();
        return Eigen::Quaterniond(Eigen::AngleAxisd(M_PI, turn));
    }
    return Eigen::Quaterniond::FromTwoVectors(axis, direction).normalized();
}

}  // namespace

std::string sanitizedName(const std::string& name) {
    std::string out;
    for (unsigned char c : name)
        out += std::isalnum(c) ? static_cast<char>(c) : '_';
    if (out.empty() || std::isdigit(static_cast<unsigned char>(out[0])))
        out = "part_" + out;
    return out;
}

ExportRig makeExportRig(const Part& part, const std::string& partName,
                        const Eigen::Affine3d& placement, double unitScale, BoneAxes axes) {
    const Skeleton& skeleton = part.skeleton;
    if (skeleton.jointCount() == 0 || !skeleton.hasJoint(skeleton.root()))
        throw Error("part '" + partName + "' has no skeleton to export");
    const PoseHierarchy hierarchy(skeleton);
    ExportRig rig;
    rig.placementRotation = Eigen::Quaterniond(placement.rotation()).normalized();
    rig.unitScale = unitScale;
    rig.nodeOfBone.assign(skeleton.boneCount(), -1);
    auto place = [&](const Vec3& x) -> Vec3 { return unitScale * (placement * x); };

    // The bones whose frame joint is each joint, then breadth first from the root.
    std::vector<std::vector<int>> bonesFrom(hierarchy.jointCount());
    for (int b = 0; b < hierarchy.boneCount(); ++b)
        if (hierarchy.reachable(hierarchy.boneHeadJoint(b)) &&
            hierarchy.boneRotationJoint(b) == hierarchy.boneTailJoint(b))
            bonesFrom[hierarchy.boneHeadJoint(b)].push_back(b);
    std::deque<std::pair<int, int>> queue;  // (bone, parent node)
    for (int b : bonesFrom[hierarchy.root()])
        queue.emplace_back(b, -1);
    while (!queue.empty()) {
        const auto [b, parent] = queue.front();
        queue.pop_front();
        const int frame = hierarchy.boneHeadJoint(b), end = hierarchy.boneTailJoint(b);
        ExportBoneNode node;
        node.bone = b;
        node.parent = parent;
        node.headJoint = hierarchy.jointId(frame);
        node.tailJoint = hierarchy.jointId(end);
        const BoneId id = skeleton.bones()[b].id;
        const auto kept = part.boneNames.find(id);
        node.name = kept != part.boneNames.end() ? sanitizedName(kept->second)
                                                 : partName + "_bone" + std::to_string(id);
        node.head = place(hierarchy.restPosition(frame));
        node.tail = place(hierarchy.restPosition(end));
        node.leaf = bonesFrom[end].empty();
        const bool minusZ = axes == BoneAxes::GltfRootLeavesMinusZ && parent < 0 && node.leaf;
        node.restFrame =
            boneFrame(minusZ ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitY()), node.tail - node.head);
        if (parent < 0) {
            node.restTranslation = node.head;
            node.restRotation = node.restFrame;
        } else {
            const ExportBoneNode& up = rig.nodes[static_cast<std::size_t>(parent)];
            node.restTranslation = up.restFrame.conjugate() * (node.head - up.head);
            node.restRotation = (up.restFrame.conjugate() * node.restFrame).normalized();
        }
        const int index = static_cast<int>(rig.nodes.size());
        rig.nodeOfBone[b] = index;
        rig.nodes.push_back(node);
        for (int child : bonesFrom[end])
            queue.emplace_back(child, index);
    }
    return rig;
}

Eigen::Affine3d ExportBoneNode::inverseBind() const {
    Eigen::Affine3d bind = Eigen::Affine3d::Identity();
    bind.translate(head);
    bind.rotate(restFrame);
    return bind.inverse(Eigen::Isometry);
}

Vec3 ExportRig::localTranslation(int node, const Pose& pose) const {
    const ExportBoneNode& n = nodes[node];
    if (n.parent >= 0)
        return n.restTranslation;
    return n.restTranslation + unitScale * (placementRotation * pose.rootTranslation);
}

Eigen::Quaterniond ExportRig::localRotation(int node, const Pose& pose) const {
    const ExportBoneNode& n = nodes[static_cast<std::size_t>(node)];
    // The bone's own rotation; a root bone's follows the whole skeleton's.
    const Eigen::Quaterniond own = pose.rotation(n.tailJoint).normalized();
    const Eigen::Quaterniond q =
        n.parent < 0 ? (pose.rotation(n.headJoint).normalized() * own).normalized() : own;
    const Eigen::Quaterniond axisAligned = placementRotation * q * placementRotation.conjugate();
    const Eigen::Quaterniond parentFrame =
        n.parent < 0 ? Eigen::Quaterniond::Identity()
                     : nodes[static_cast<std::size_t>(n.parent)].restFrame;
    return (parentFrame.conjugate() * axisAligned * n.restFrame).normalized();
}

}  // namespace rigmesh
