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
    root_ = skeleton.indexOfJoint(skeleton.root());
    parent_.assign(n, -1);
    children_.assign(n, {});
    std::vector<bool> seen(n, false);
    seen[root_] = true;
    order_.push_back(root_);
    for (std::size_t k = 0; k < order_.size(); ++k) {
        const int j = order_[k];
        for (const auto& [bone, other] : incident[j]) {
            if (!seen[other]) {
                seen[other] = true;
                parent_[other] = j;
                children_[j].push_back(other);
                order_.push_back(other);
            }
        }
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
