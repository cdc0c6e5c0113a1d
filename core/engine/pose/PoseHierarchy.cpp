#include "pose/PoseHierarchy.h"

#include <string>

#include "base/Error.h"

namespace rigmesh {

PoseHierarchy::PoseHierarchy(const Skeleton& skeleton) {
    const int n = skeleton.jointCount();
    if (n == 0)
        throw Error(MessageId::PoseNeedsJoints);
    if (!skeleton.hasJoint(skeleton.root()))
        throw Error(MessageId::PoseNeedsRoot);
    jointIds_.reserve(n);
    restPositions_.reserve(n);
    for (int j = 0; j < n; ++j) {
        jointIds_.push_back(skeleton.joints()[j].id);
        restPositions_.push_back(skeleton.joints()[j].position);
        index_.emplace(jointIds_.back(), j);
    }

    // Incident (bone, other joint) lists, then breadth first from the root.
    const int b = skeleton.boneCount();
    std::vector<std::vector<std::pair<int, int>>> incident(n);
    std::vector<int> head(b, -1), tail(b, -1);
    for (int i = 0; i < b; ++i) {
        const Bone& bone = skeleton.bones()[i];
        if (!skeleton.hasJoint(bone.head) || !skeleton.hasJoint(bone.tail) ||
            bone.head == bone.tail)
            continue;
        head[i] = skeleton.indexOfJoint(bone.head);
        tail[i] = skeleton.indexOfJoint(bone.tail);
        incident[head[i]].push_back({i, tail[i]});
        incident[tail[i]].push_back({i, head[i]});
    }
    // Attached chain roots per bone they hang from; root chains apart.
    std::vector<std::vector<int>> chainsOf(b);
    std::vector<int> rootChains;
    for (const auto& [joint, parent] : skeleton.attachments()) {
        if (!skeleton.hasJoint(joint))
            continue;
        if (parent == kNoBone)
            rootChains.push_back(skeleton.indexOfJoint(joint));
        else if (skeleton.hasBone(parent))
            chainsOf[skeleton.indexOfBone(parent)].push_back(skeleton.indexOfJoint(joint));
    }
    root_ = skeleton.indexOfJoint(skeleton.root());
    parent_.assign(n, -1);
    attached_.assign(n, false);
    children_.assign(n, {});
    std::vector<int> incoming(n, -1);  // the bone each joint was reached by
    std::vector<bool> seen(n, false);
    auto reach = [&](int joint, int parent, int bone) {
        if (seen[joint])
            return;
        seen[joint] = true;
        parent_[joint] = parent;
        attached_[joint] = bone < 0;
        incoming[joint] = bone;
        children_[parent].push_back(joint);
        order_.push_back(joint);
    };
    seen[root_] = true;
    order_.push_back(root_);
    for (int chain : rootChains)
        reach(chain, root_, -1);
    for (std::size_t k = 0; k < order_.size(); ++k) {
        const int j = order_[k];
        // A chain hanging from the bone that ends here follows this joint.
        if (incoming[j] >= 0)
            for (int chain : chainsOf[incoming[j]])
                reach(chain, j, -1);
        for (const auto& [bone, other] : incident[j])
            reach(other, j, bone);
    }

    // A bone's head is whichever end the search reached first; a bone with
    // an unknown joint has its known one (or the root) as both ends.
    boneHead_.assign(b, -1);
    boneTail_.assign(b, -1);
    boneRotation_.assign(b, -1);
    for (int i = 0; i < b; ++i) {
        if (head[i] < 0) {
            const Bone& bone = skeleton.bones()[i];
            const int h = skeleton.hasJoint(bone.head) ? skeleton.indexOfJoint(bone.head) : root_;
            boneHead_[i] = boneTail_[i] = boneRotation_[i] = h;
            continue;
        }
        const bool reversed = parent_[head[i]] == tail[i];
        boneHead_[i] = reversed ? tail[i] : head[i];
        boneTail_[i] = reversed ? head[i] : tail[i];
        boneRotation_[i] = parent_[boneTail_[i]] == boneHead_[i] ? boneTail_[i] : boneHead_[i];
    }
}

int PoseHierarchy::indexOf(JointId id) const {
    const auto it = index_.find(id);
    if (it == index_.end())
        throw Error(MessageId::SkeletonHasNoJoint, id);

    return it->second;
}

}  // namespace rigmesh
