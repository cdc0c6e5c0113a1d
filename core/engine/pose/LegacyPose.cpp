#include "pose/LegacyPose.h"

namespace rigmesh {

Pose poseFromJointRotations(const PoseHierarchy& h, const Pose& legacy) {
    Pose pose;
    pose.rootTranslation = legacy.rootTranslation;
    for (int j : h.parentFirstOrder()) {
        if (j == h.root())
            continue;
        const auto old = legacy.rotations.find(h.jointId(h.parent(j)));
        if (old != legacy.rotations.end())
            pose.rotations.emplace(h.jointId(j), old->second);
    }
    return pose;
}

Clip clipFromJointRotations(const PoseHierarchy& h, const Clip& legacy) {
    Clip clip = legacy;
    for (const auto& [time, pose] : legacy.keys()) {
        clip.eraseExactKey(time);
        clip.insertExactKey(time, poseFromJointRotations(h, pose));
    }
    return clip;
}

void setJointRotations(const PoseHierarchy& h,
                       const std::map<JointId, Eigen::Quaterniond>& jointRotations, Pose& pose) {
    for (const auto& [joint, rotation] : jointRotations)
        for (int child : h.children(h.indexOf(joint)))
            pose.setRotation(h.jointId(child), rotation);
}

}  // namespace rigmesh
