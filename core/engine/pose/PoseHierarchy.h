// The tree structure posing needs, computed once from a skeleton: every
// joint's parent by breadth-first search from the root over the bones in
// either direction (so a skeleton not yet reoriented still poses correctly),
// a parent-first joint order, and for every bone its head (the joint nearer
// the root, about which it turns), its tail, and the joint whose rotation
// carries it (Pose.h: the tail). Dense indices follow skeleton.joints() and
// skeleton.bones().
//
// The root joint of an attached chain (Skeleton.h: a disconnected bone's
// head) has as parent the tail of the bone it hangs from, whose transform
// it follows rigidly (no bone between them: attached(joint) is true); a
// root chain's root hangs from the skeleton's root joint the same way.
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
    int boneCount() const { return static_cast<int>(boneHead_.size()); }
    int root() const { return root_; }
    JointId jointId(int joint) const { return jointIds_[joint]; }
    const Vec3& restPosition(int joint) const { return restPositions_[joint]; }
    // -1 for the root and for joints the root cannot reach.
    int parent(int joint) const { return parent_[joint]; }
    // True for an attached chain's root: it hangs rigidly from its parent
    // joint's transform, without a bone between them.
    bool attached(int joint) const { return attached_[joint]; }
    const std::vector<int>& children(int joint) const { return children_[joint]; }
    // Joints reachable from the root, each after its parent.
    const std::vector<int>& parentFirstOrder() const { return order_; }
    bool reachable(int joint) const { return joint == root_ || parent_[joint] >= 0; }
    // The bone's joint nearer the root (the pivot it turns about) and the
    // other one.
    int boneHeadJoint(int bone) const { return boneHead_[bone]; }
    int boneTailJoint(int bone) const { return boneTail_[bone]; }
    // The joint whose pose rotation (and FK transform) the bone has: its
    // tail, whose only incoming bone it is. A bone the breadth-first tree
    // left out (one closing a cycle) moves rigidly with the bone ending at
    // its head; one the root cannot reach keeps its head (identity).
    int boneRotationJoint(int bone) const { return boneRotation_[bone]; }
    // Throws Error on an unknown id.
    int indexOf(JointId id) const;

  private:
    std::vector<JointId> jointIds_;
    std::vector<Vec3> restPositions_;
    std::vector<int> parent_;
    std::vector<bool> attached_;
    std::vector<std::vector<int>> children_;
    std::vector<int> order_;
    std::vector<int> boneHead_, boneTail_, boneRotation_;
    std::unordered_map<JointId, int> index_;
    int root_ = -1;
};

}  // namespace rigmesh
