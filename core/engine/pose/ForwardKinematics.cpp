#include "pose/ForwardKinematics.h"

#include <string>

#include "base/Error.h"

namespace rigmesh {

namespace {

Eigen::Quaterniond checkedRotation(const Pose& pose, JointId joint) {
    const Eigen::Quaterniond q = pose.rotation(joint);
    const double norm2 = q.coeffs().squaredNorm();
    if (!q.coeffs().allFinite() || norm2 == 0.0)
        throw Error(MessageId::PoseRotationInvalid, joint);
    // Already-unit quaternions (the identity in particular) stay untouched.
    return norm2 == 1.0 ? q : q.normalized();
}

}  // namespace

PosedSkeleton forwardKinematics(const PoseHierarchy& h, const Pose& pose) {
    if (!pose.rootTranslation.allFinite())
        throw Error(MessageId::PoseTranslationNotFinite);

    PosedSkeleton posed;
    posed.jointTransforms.assign(h.jointCount(), RigidTransform::identity());
    posed.jointPositions.resize(h.jointCount());
    for (int j = 0; j < h.jointCount(); ++j)
        posed.jointPositions[j] = h.restPosition(j);

    for (int j : h.parentFirstOrder()) {
        RigidTransform world;
        if (j == h.root()) {
            world = RigidTransform::rotationAbout(checkedRotation(pose, h.jointId(j)),
                                                  h.restPosition(j));
            world.translation += pose.rootTranslation;
        } else if (h.attached(j)) {
            // An attached chain's root follows its parent bone's frame
            // rigidly; its own rotation turns the chain about it.
            world = posed.jointTransforms[h.parent(j)] *
                    RigidTransform::rotationAbout(checkedRotation(pose, h.jointId(j)),
                                                  h.restPosition(j));
        } else {
            // The bone from the parent to j turns about its head, the parent.
            const int parent = h.parent(j);
            world = posed.jointTransforms[parent] *
                    RigidTransform::rotationAbout(checkedRotation(pose, h.jointId(j)),
                                                  h.restPosition(parent));
        }
        posed.jointTransforms[j] = world;
        posed.jointPositions[j] = world.apply(h.restPosition(j));
    }

    posed.boneTransforms.reserve(h.boneCount());
    for (int b = 0; b < h.boneCount(); ++b)
        posed.boneTransforms.push_back(posed.jointTransforms[h.boneRotationJoint(b)]);
    return posed;
}

PosedSkeleton forwardKinematics(const Skeleton& skeleton, const Pose& pose) {
    return forwardKinematics(PoseHierarchy(skeleton), pose);
}

}  // namespace rigmesh
