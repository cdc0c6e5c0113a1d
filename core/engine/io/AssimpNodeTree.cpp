#include "io/AssimpNodeTree.h"

#include <algorithm>
#include <unordered_map>

#include "io/AssimpConversions.h"

namespace rigmesh {
namespace {

// The key before `ticks` and how far towards the next one it lies. A binary
// search (the import samples every key time, so a scan made it quadratic:
// 48,000 key times took 26 s); defined for keys out of order too, which a
// broken file may hold.
template <typename Key>
std::pair<std::size_t, double> bracket(const Key* keys, unsigned count, double ticks) {
    if (count <= 1 || ticks <= keys[0].mTime)
        return {0, 0.0};
    // The first k >= 1 with ticks <= keys[k].mTime, or count.
    unsigned low = 1, high = count;
    while (low < high) {
        const unsigned middle = low + (high - low) / 2;
        if (keys[middle].mTime < ticks)
            low = middle + 1;
        else
            high = middle;
    }
    if (low == count)
        return {count - 1, 0.0};
    const double span = keys[low].mTime - keys[low - 1].mTime;
    return {low - 1, span > 0 ? (ticks - keys[low - 1].mTime) / span : 1.0};
}

Vec3 sampleVector(const aiVectorKey* keys, unsigned count, const Vec3& fallback, double ticks) {
    if (count == 0)
        return fallback;
    const auto [k, s] = bracket(keys, count, ticks);
    const Vec3 a = fromAi(keys[k].mValue);
    return s == 0.0 ? a : Vec3(a + s * (fromAi(keys[k + 1].mValue) - a));
}

}  // namespace

AssimpNodeTree::AssimpNodeTree(const aiScene& scene, double scale) {
    scale_ = Eigen::Affine3d(Eigen::Scaling(scale));
    if (scene.mRootNode == nullptr)
        return;
    // Every node by the children lists, and the parent each names itself.
    std::vector<const aiNode*> all;
    std::unordered_map<const aiNode*, const aiNode*> listedUnder;
    std::vector<const aiNode*> stack = {scene.mRootNode};
    listedUnder[scene.mRootNode] = nullptr;
    while (!stack.empty()) {
        const aiNode* node = stack.back();
        stack.pop_back();
        all.push_back(node);
        for (unsigned c = node->mNumChildren; c-- > 0;)
            if (listedUnder.emplace(node->mChildren[c], node).second)
                stack.push_back(node->mChildren[c]);
    }
    // Assimp 5.2.5's Half-Life MDL reader lists every bone under one node
    // but sets each bone's mParent to its real parent bone: mParent wins
    // when it is another node of the scene and no loop follows from it.
    std::unordered_map<const aiNode*, const aiNode*> parentOf;
    for (const aiNode* node : all) {
        const aiNode* named = node->mParent;
        parentOf[node] = named != nullptr && named != node && listedUnder.contains(named)
                             ? named
                             : listedUnder.at(node);
    }
    // A node whose parents do not lead to the root (a loop) keeps its list's.
    for (bool changed = true; changed;) {
        changed = false;
        for (const aiNode* node : all) {
            std::size_t steps = 0;
            const aiNode* up = parentOf.at(node);
            while (up != nullptr && steps++ <= all.size())
                up = parentOf.at(up);
            if (up != nullptr && parentOf.at(node) != listedUnder.at(node)) {
                parentOf[node] = listedUnder.at(node);
                changed = true;
            }
        }
    }
    std::unordered_map<const aiNode*, std::vector<const aiNode*>> children;
    for (const aiNode* node : all)  // in list order
        if (parentOf.at(node) != nullptr)
            children[parentOf.at(node)].push_back(node);
    // Parent first, children in their list order.
    std::vector<std::pair<const aiNode*, int>> order = {{scene.mRootNode, -1}};
    while (!order.empty()) {
        const auto [node, parent] = order.back();
        order.pop_back();
        const int index = static_cast<int>(nodes_.size());
        nodes_.push_back(node);
        parents_.push_back(parent);
        const Eigen::Affine3d local = fromAi(node->mTransformation);
        rest_.push_back(parent < 0 ? scale_ * local
                                   : rest_[static_cast<std::size_t>(parent)] * local);
        byName_.emplace(node->mName.C_Str(), index);
        const auto list = children.find(node);
        if (list != children.end())
            for (auto it = list->second.rbegin(); it != list->second.rend(); ++it)
                order.emplace_back(*it, index);
    }
}

int AssimpNodeTree::find(const std::string& name) const {
    const auto it = byName_.find(name);
    return it == byName_.end() ? -1 : it->second;
}

std::vector<Eigen::Affine3d> AssimpNodeTree::animatedGlobals(const aiAnimation& animation,
                                                             double ticks) const {
    std::vector<Eigen::Affine3d> locals;
    for (const aiNode* node : nodes_)
        locals.push_back(fromAi(node->mTransformation));
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        const int i = find(animation.mChannels[c]->mNodeName.C_Str());
        if (i >= 0)
            locals[static_cast<std::size_t>(i)] =
                sampleChannel(*animation.mChannels[c], ticks, locals[static_cast<std::size_t>(i)]);
    }
    std::vector<Eigen::Affine3d> globals(nodes_.size());
    for (std::size_t i = 0; i < nodes_.size(); ++i)  // parent first by construction
        globals[i] = parents_[i] < 0 ? scale_ * locals[i]
                                     : globals[static_cast<std::size_t>(parents_[i])] * locals[i];
    return globals;
}

Eigen::Affine3d sampleChannel(const aiNodeAnim& channel, double ticks,
                              const Eigen::Affine3d& rest) {
    Eigen::Matrix3d restRotation, restScaling;
    rest.computeRotationScaling(&restRotation, &restScaling);
    const Vec3 position =
        sampleVector(channel.mPositionKeys, channel.mNumPositionKeys, rest.translation(), ticks);
    const Vec3 scaling =
        sampleVector(channel.mScalingKeys, channel.mNumScalingKeys, restScaling.diagonal(), ticks);
    Eigen::Quaterniond rotation(restRotation);
    if (channel.mNumRotationKeys > 0) {
        const auto [k, s] = bracket(channel.mRotationKeys, channel.mNumRotationKeys, ticks);
        rotation = fromAi(channel.mRotationKeys[k].mValue).normalized();
        if (s != 0.0)
            rotation = rotation.slerp(s, fromAi(channel.mRotationKeys[k + 1].mValue).normalized());
    }
    Eigen::Affine3d out = Eigen::Affine3d::Identity();
    out.translate(position);
    out.rotate(rotation);
    out.scale(scaling);
    return out;
}

}  // namespace rigmesh
