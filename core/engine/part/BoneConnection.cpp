#include "part/BoneConnection.h"

#include <limits>
#include <set>

#include "base/Error.h"

namespace rigmesh {

std::optional<BoneId> firstDisconnectedBone(const Skeleton& skeleton) {
    if (skeleton.isConnectedTree())
        return std::nullopt;
    for (BoneId id : skeleton.bonesInHierarchyOrder())
        if (skeleton.isAttached(skeleton.bone(id).head))
            return id;
    return std::nullopt;
}

std::string boneLabel(const Part& part, BoneId bone) {
    const auto name = part.boneNames.find(bone);
    return name != part.boneNames.end() ? "'" + name->second + "'" : std::to_string(bone);
}

void requireConnectedSkeleton(const Part& part) {
    if (const std::optional<BoneId> bone = firstDisconnectedBone(part.skeleton))
        throw Error(MessageId::BoneNotConnected, boneLabel(part, *bone));
}

namespace {

// The joints of the chain rooted at `start` and of every chain hanging from
// its bones, all the way down.
std::set<JointId> carriedJoints(const Skeleton& skeleton, JointId start) {
    std::set<JointId> joints{start};
    std::vector<JointId> stack{start};
    while (!stack.empty()) {
        const JointId joint = stack.back();
        stack.pop_back();
        for (BoneId bone : skeleton.childrenOf(joint)) {
            const JointId tail = skeleton.bone(bone).tail;
            for (JointId next : skeleton.attachedTo(bone))
                if (joints.insert(next).second)
                    stack.push_back(next);
            if (joints.insert(tail).second)
                stack.push_back(tail);
        }
    }
    return joints;
}

}  // namespace

Part connectBone(const Part& part, BoneId bone) {
    Skeleton skeleton = part.skeleton;
    if (!skeleton.hasBone(bone))
        throw Error(MessageId::PartHasNoBone, bone);
    const JointId head = skeleton.bone(bone).head;
    if (head == skeleton.root())
        throw Error(MessageId::ConnectBoneHasNoParent, boneLabel(part, bone));
    if (!skeleton.isAttached(head))
        throw Error(MessageId::ConnectBoneAlreadyConnected, boneLabel(part, bone));
    JointId onto = kNoJoint;
    if (const BoneId parent = skeleton.attachments().at(head); parent != kNoBone) {
        onto = skeleton.bone(parent).tail;
    } else {
        // A further root chain: the nearest joint it does not carry.
        const std::set<JointId> carried = carriedJoints(skeleton, head);
        const Vec3& at = skeleton.joint(head).position;
        double nearest = std::numeric_limits<double>::infinity();
        for (const Joint& joint : skeleton.joints())
            if (!carried.contains(joint.id) && (joint.position - at).norm() < nearest) {
                nearest = (joint.position - at).norm();
                onto = joint.id;
            }
    }
    const std::vector<BoneId> moved = skeleton.childrenOf(head);
    skeleton.mergeJoints(onto, head);
    skeleton.reorient();
    if (const std::vector<Message> problems = skeleton.validate(); !problems.empty())
        throw Error(MessageId::BoneEditInvalidResult, problems.front());
    Part out = part;
    out.skeleton = std::move(skeleton);
    for (BoneId id : moved)
        out.boneFrames.erase(id);
    return out;
}

}  // namespace rigmesh
