// The tree structure posing needs, computed once from a skeleton: every
// joint's parent by breadth-first search from the root over the bones in
// either direction (so a skeleton not yet reoriented still poses correctly),
// a parent-first joint order, and for every bone the joint nearer the root
// (whose rotation carries the bone) and the farther one. Dense indices follow
// skeleton.joints() and skeleton.bones().
#pragma once

#include <unordered_map>
#include <vector>

#include "rig/Skeleton.h"

namespace rigmesh {

class PoseHierarchy {
  public:
    // Throws Error if the skeleton has no joints or its root is unknown.
    explicit PoseHierarchy(const Skeleton& skeleton);

    int jointCount() const { return static_cast<int>(jointIds_.size()); }
    int boneCount() const { return static_cast<int>(boneFrameJoint_.size()); }
    int root() const { return root_; }
    JointId jointId(int joint) const { return jointIds_[joint]; }
    const Vec3& restPosition(int joint) const { return restPositions_[joint]; }
    // -1 for the root and for joints the root cannot reach.
    int parent(int joint) const { return parent_[joint]; }
    const std::vector<int>& children(int joint) const { return children_[joint]; }
    // Joints reachable from the root, each after its parent.
    const std::vector<int>& parentFirstOrder() const { return order_; }
    bool reachable(int joint) const { return joint == root_ || parent_[joint] >= 0; }
    // The bone's joint nearer the root (its frame) and the other one.
    int boneFrameJoint(int bone) const { return boneFrameJoint_[bone]; }
    int boneEndJoint(int bone) const { return boneEndJoint_[bone]; }
    // Throws Error on an unknown id.
    int indexOf(JointId id) const;

  private:
    std::vector<JointId> jointIds_;
    std::vector<Vec3> restPositions_;
    std::vector<int> parent_;
    std::vector<std::vector<int>> children_;
    std::vector<int> order_;
    std::vector<int> boneFrameJoint_, boneEndJoint_;
    std::unordered_map<JointId, int> index_;
    int root_ = -1;
};

}  // namespace rigmesh
