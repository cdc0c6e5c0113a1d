#include "pose/PoseHierarchy.h"

#include <string>

#include "base/Error.h"

namespace rigmesh {

PoseHierarchy::PoseHierarchy(const Skeleton& skeleton) {
    const int n = skeleton.jointCount();
    if (n == 0)
        throw Error("Cannot pose a skeleton without joints.");
    if (!skeleton.hasJoint(skeleton.root()))
        throw Error("Cannot pose a skeleton without a valid root joint.");
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

    // A bone hangs from whichever end the search reached first; bones the
    // root cannot reach keep their head as frame.
    boneFrameJoint_.assign(b, -1);
    boneEndJoint_.assign(b, -1);
    for (int i = 0; i < b; ++i) {
        if (head[i] < 0) {
            const Bone& bone = skeleton.bones()[i];
            const int h = skeleton.hasJoint(bone.head) ? skeleton.indexOfJoint(bone.head) : root_;
            boneFrameJoint_[i] = boneEndJoint_[i] = h;
        } else if (parent_[head[i]] == tail[i]) {
            boneFrameJoint_[i] = tail[i];
            boneEndJoint_[i] = head[i];
        } else {
            boneFrameJoint_[i] = head[i];
            boneEndJoint_[i] = tail[i];
        }
    }
}

int PoseHierarchy::indexOf(JointId id) const {
    const auto it = index_.find(id);
    if (it == index_.end())
        throw Error("The skeleton has no joint " + std::to_string(id) + ".");
    return it->second;
}

}  // namespace rigmesh
