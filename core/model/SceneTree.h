// The tree the outliner shows, apart from the Qt item model adapter (as in
// Qt's editabletreemodel example): root -> parts (document order) -> one
// "Skeleton" node each -> joints following the skeleton hierarchy (root
// joint first, children in bone order). Joints unreachable from the root
// (a broken skeleton) hang directly under the skeleton node after it.
// Nodes carry ids only; names and figures are read from the document.
#pragma once

#include <memory>
#include <vector>

#include "model/PartNode.h"
#include "rig/Skeleton.h"

namespace rigmesh::model {

class SceneNode {
  public:
    enum class Kind { Root, Part, Skeleton, Joint };

    SceneNode(Kind kind, PartId part = kNoPart, JointId joint = kNoJoint)
        : kind_(kind), part_(part), joint_(joint) {}
    SceneNode(const SceneNode&) = delete;
    SceneNode& operator=(const SceneNode&) = delete;

    Kind kind() const { return kind_; }
    PartId partId() const { return part_; }
    JointId jointId() const { return joint_; }

    SceneNode* parent() const { return parent_; }
    int childCount() const { return static_cast<int>(children_.size()); }
    SceneNode* child(int row) const;  // nullptr when out of range
    int row() const;                  // position under the parent; 0 for the root
    // The child for `part` (root) or `joint` (anywhere below), or nullptr.
    SceneNode* findPart(PartId part) const;
    SceneNode* findJoint(JointId joint) const;

    SceneNode* insertChild(int row, std::unique_ptr<SceneNode> node);
    std::unique_ptr<SceneNode> takeChild(int row);

  private:
    Kind kind_;
    PartId part_;
    JointId joint_;
    SceneNode* parent_ = nullptr;
    std::vector<std::unique_ptr<SceneNode>> children_;
};

// A part node with its skeleton subtree.
std::unique_ptr<SceneNode> makePartNode(const PartNode& part);
// The "Skeleton" node of a part with its joint subtree.
std::unique_ptr<SceneNode> makeSkeletonNode(PartId part, const Skeleton& skeleton);

}  // namespace rigmesh::model
