#include "merge/SkeletonJoin.h"

#include <algorithm>

#include "base/Error.h"
#include "rig/BoneSegment.h"

namespace rigmesh {

namespace {

// A split closer than this fraction of the bone's length to one of its ends
// snaps to that end instead of making a near-zero bone.
constexpr double kSplitEndFraction = 0.05;

}  // namespace

SkeletonJoin joinSkeletons(const Skeleton& target, const Skeleton& dragged,
                           const SkeletonJoinRequest& request, double minimumBone) {
    if (!dragged.hasJoint(request.draggedJoint))
        throw Error(MessageId::MergeNoDraggedJoint, request.draggedJoint);
    SkeletonJoin join;
    join.skeleton = target;
    Skeleton& merged = join.skeleton;

    switch (request.mode) {
        case MergeMode::Snap:
        case MergeMode::Connect:
            if (!target.hasJoint(request.targetJoint))
                throw Error(MessageId::MergeNoTargetJoint, request.targetJoint);
            join.meetingJoint = request.targetJoint;
            break;
        case MergeMode::Split: {
            if (!target.hasBone(request.targetBone))
                throw Error(MessageId::MergeNoTargetBone, request.targetBone);
            const Bone& bone = target.bone(request.targetBone);
            const BoneSegment segment{target.joint(bone.head).position,
                                      target.joint(bone.tail).position};
            const double t = closestSegmentParameter(request.splitPoint, segment);
            const double length = (segment.tail - segment.head).norm();
            const double snap =
                length > 0.0 ? std::max(kSplitEndFraction, minimumBone / length) : 1.0;
            if (t < snap && t <= 0.5) {
                join.meetingJoint = bone.head;
            } else if (t > 1.0 - snap) {
                join.meetingJoint = bone.tail;
            } else {
                const JointId oldTail = bone.tail;
                join.meetingJoint = merged.splitBone(
                    request.targetBone, segment.head + t * (segment.tail - segment.head));
                for (BoneId id : merged.bonesAt(join.meetingJoint))
                    if (id != request.targetBone && merged.bone(id).tail == oldTail)
                        join.splitTail = id;
            }
            break;
        }
    }

    const Vec3 meetingPoint = merged.joint(join.meetingJoint).position;
    if (request.mode != MergeMode::Connect)
        join.draggedTranslation = meetingPoint - dragged.joint(request.draggedJoint).position;

    for (const Joint& joint : dragged.joints()) {
        const bool meets = request.mode != MergeMode::Connect && joint.id == request.draggedJoint;
        join.draggedJoints[joint.id] =
            meets ? join.meetingJoint : merged.addJoint(joint.position + join.draggedTranslation);
    }
    for (const Bone& bone : dragged.bones())
        join.draggedBones[bone.id] =
            merged.addBone(join.draggedJoints.at(bone.head), join.draggedJoints.at(bone.tail));
    if (request.mode == MergeMode::Connect) {
        const JointId from = join.draggedJoints.at(request.draggedJoint);
        const double apart = (merged.joint(from).position - meetingPoint).norm();
        if (apart == 0.0)
            throw Error(MessageId::MergeJointsCoincide);
        if (apart < minimumBone)
            throw Error(MessageId::MergeJointsTooClose, shortNumber(apart),
                        shortNumber(minimumBone));

        join.connectingBone = merged.addBone(join.meetingJoint, from);
    }
    return join;
}

}  // namespace rigmesh
