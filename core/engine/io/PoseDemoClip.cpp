#include "io/PoseDemoClip.h"

#include "base/Error.h"
#include "pose/InverseKinematics.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh {

Pose poseDemoBend(const Part& part) {
    const Skeleton& skeleton = part.skeleton;
    if (skeleton.boneCount() == 0)
        throw Error(MessageId::PoseDemoNeedsBones);
    const PoseHierarchy hierarchy(skeleton);
    const Vec3& root = hierarchy.restPosition(hierarchy.root());
    int end = -1;
    for (int j : hierarchy.parentFirstOrder())
        if (hierarchy.children(j).empty() &&
            (end < 0 || (hierarchy.restPosition(j) - root).norm() >
                            (hierarchy.restPosition(end) - root).norm()))
            end = j;
    if (end < 0 || hierarchy.parent(end) < 0)
        throw Error(MessageId::PoseDemoNeedsBones);
    double chain = 0;
    for (int j = end; hierarchy.parent(j) >= 0; j = hierarchy.parent(j))
        chain += (hierarchy.restPosition(j) - hierarchy.restPosition(hierarchy.parent(j))).norm();
    const Vec3 direction =
        (hierarchy.restPosition(end) - hierarchy.restPosition(hierarchy.parent(end))).normalized();
    Vec3 side(-direction.y(), direction.x(), 0.0);
    if (side.norm() < 1e-6)
        side = Vec3::UnitX();
    const Vec3 target = hierarchy.restPosition(end) + 0.5 * chain * side.normalized();
    return dragJoint(hierarchy, restPose(skeleton), hierarchy.jointId(end), target).pose;
}

Clip poseDemoClip(const Part& part) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Linear;
    clip.setKey(0.0, restPose(part.skeleton));
    clip.setKey(0.5, poseDemoBend(part));
    clip.setKey(1.0, restPose(part.skeleton));
    return clip;
}

}  // namespace rigmesh
