#include "pose/PoseMirror.h"

namespace rigmesh {

Pose mirroredPose(const Skeleton& skeleton, const Pose& pose, const PartSymmetry& symmetry) {
    Pose mirrored;
    mirrored.rootTranslation = symmetry.plane.reflectDirection(pose.rootTranslation);
    for (const auto& [joint, q] : pose.rotations) {
        if (!skeleton.hasJoint(joint))
            continue;
        const auto image = symmetry.joints.find(joint);
        const JointId to = image != symmetry.joints.end() ? image->second : joint;
        // The rotation of the bone ending at `to` (Pose.h) is the mirror of
        // the one ending at `joint`: M R M, M the reflection.
        mirrored.setRotation(to, symmetry.plane.reflectRotation(q).normalized());
    }
    return mirrored;
}

}  // namespace rigmesh
