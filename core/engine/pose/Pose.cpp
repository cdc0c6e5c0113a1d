#include "pose/Pose.h"

namespace rigmesh {

bool Pose::isFinite() const {
    if (!rootTranslation.allFinite())
        return false;
    for (const auto& [joint, q] : rotations) {
        if (!q.coeffs().allFinite() || q.coeffs().squaredNorm() == 0.0)
            return false;
    }
    return true;
}

Pose restPose(const Skeleton& skeleton) {
    Pose pose;
    for (const Joint& joint : skeleton.joints())
        pose.rotations.emplace(joint.id, Eigen::Quaterniond::Identity());
    return pose;
}

}  // namespace rigmesh
