#include "model/SceneTree.h"

#include <algorithm>
#include <unordered_set>

namespace rigmesh::model {

SceneNode* SceneNode::child(int row) const {
    return row >= 0 && row < childCount() ? children_[row].get() : nullptr;
}

int SceneNode::row() const {
    if (!parent_)
        return 0;
    const auto& siblings = parent_->children_;
    const auto it = std::find_if(siblings.begin(), siblings.end(),
                                 [this](const auto& node) { return node.get() == this; });
    return static_cast<int>(it - siblings.begin());
}

SceneNode* SceneNode::findPart(PartId part) const {
    for (const auto& node : children_)
        if (node->kind_ == Kind::Part && node->part_ == part)
            return node.get();
    return nullptr;
}

SceneNode* SceneNode::findJoint(JointId joint) const {
    for (const auto& node : children_) {
        if (node->kind_ == Kind::Joint && node->joint_ == joint)
            return node.get();
        if (SceneNode* found = node->findJoint(joint))
            return found;
    }
    return nullptr;
}

SceneNode* SceneNode::insertChild(int row, std::unique_ptr<SceneNode> node) {
    row = std::clamp(row, 0, childCount());
    node->parent_ = this;
    return children_.insert(children_.begin() + row, std::move(node))->get();
}

std::unique_ptr<SceneNode> SceneNode::takeChild(int row) {
    if (row < 0 || row >= childCount())
        return nullptr;
    std::unique_ptr<SceneNode> node = std::move(children_[row]);
    children_.erase(children_.begin() + row);
    node->parent_ = nullptr;
    return node;
}

namespace {

void addJointSubtree(SceneNode& parent, PartId part, const Skeleton& skeleton, JointId joint,
                     std::unordered_set<JointId>& placed) {
    if (!placed.insert(joint).second)
        return;  // a cycle: each joint appears once
    SceneNode* node = parent.insertChild(
        parent.childCount(), std::make_unique<SceneNode>(SceneNode::Kind::Joint, part, joint));
    for (BoneId bone : skeleton.childrenOf(joint))
        addJointSubtree(*node, part, skeleton, skeleton.bone(bone).tail, placed);
    // Chains hanging from the bone that ends here (disconnected bones).
    for (const auto& [chain, bone] : skeleton.attachments())
        if (skeleton.hasBone(bone) && skeleton.bone(bone).tail == joint)
            addJointSubtree(*node, part, skeleton, chain, placed);
}

}  // namespace

std::unique_ptr<SceneNode> makeSkeletonNode(PartId part, const Skeleton& skeleton) {
    auto node = std::make_unique<SceneNode>(SceneNode::Kind::Skeleton, part);
    std::unordered_set<JointId> placed;
    if (skeleton.hasJoint(skeleton.root()))
        addJointSubtree(*node, part, skeleton, skeleton.root(), placed);
    for (const Joint& joint : skeleton.joints())
        addJointSubtree(*node, part, skeleton, joint.id, placed);
    return node;
}

std::unique_ptr<SceneNode> makePartNode(const PartNode& part) {
    auto node = std::make_unique<SceneNode>(SceneNode::Kind::Part, part.id);
    static const Skeleton kEmpty;
    node->insertChild(0, makeSkeletonNode(part.id, part.part ? part.part->skeleton : kEmpty));
    return node;
}

}  // namespace rigmesh::model
