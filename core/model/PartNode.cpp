#include "model/PartNode.h"

#include <QCoreApplication>

namespace rigmesh::model {

rigmesh::Pose restPoseOf(const PartNode& node) {
    return node.part ? rigmesh::restPose(node.part->skeleton) : rigmesh::Pose{};
}

bool identicalPoses(const rigmesh::Pose& a, const rigmesh::Pose& b) {
    if (a.rootTranslation != b.rootTranslation || a.rotations.size() != b.rotations.size())
        return false;
    auto j = b.rotations.begin();
    for (auto i = a.rotations.begin(); i != a.rotations.end(); ++i, ++j) {
        if (i->first != j->first || i->second.coeffs() != j->second.coeffs())
            return false;
    }
    return true;
}

QString jointDisplayName(rigmesh::JointId joint) {
    return QCoreApplication::translate("rigmesh::model::PartNode", "Joint %1").arg(joint);
}

}  // namespace rigmesh::model
