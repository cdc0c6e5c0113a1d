#include "model/PartNode.h"

#include <QCoreApplication>

namespace rigmesh::model {

Eigen::AlignedBox3d worldBounds(const PartNode& node) {
    Eigen::AlignedBox3d box;
    if (node.part)
        for (const Vec3& v : node.part->mesh.vertices)
            box.extend(node.placement.toWorld(v));
    return box;
}

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

bool identicalClips(const rigmesh::Clip& a, const rigmesh::Clip& b) {
    if (a.name != b.name || a.framesPerSecond() != b.framesPerSecond() ||
        a.interpolation != b.interpolation || a.mode != b.mode || a.keyCount() != b.keyCount())
        return false;
    auto j = b.keys().begin();
    for (auto i = a.keys().begin(); i != a.keys().end(); ++i, ++j) {
        if (i->first != j->first || !identicalPoses(i->second, j->second))
            return false;
    }
    return true;
}

rigmesh::Clip emptiedClip(const rigmesh::Clip& clip) {
    rigmesh::Clip out(clip.framesPerSecond());
    out.interpolation = clip.interpolation;
    out.mode = clip.mode;
    out.name = clip.name;
    return out;
}

QString jointDisplayName(rigmesh::JointId joint) {
    return QCoreApplication::translate("rigmesh::model::PartNode", "Joint %1").arg(joint);
}

}  // namespace rigmesh::model
