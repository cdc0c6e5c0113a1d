#include "io/AssimpBoneHints.h"

#include <cmath>
#include <cstdint>

#include "io/AssimpConversions.h"
#include "io/BoneTipHints.h"

namespace rigmesh {
namespace {

// World bind transform of a bone: meshGlobal * inverse(offset).
Vec3 bindHead(const aiBone& bone, const Eigen::Affine3d& meshGlobal) {
    const Eigen::Matrix4d bind =
        meshGlobal.matrix() * fromAi(bone.mOffsetMatrix).matrix().inverse();
    return bind.block<3, 1>(0, 3);
}

bool hasWeight(const aiBone& bone) {
    for (unsigned w = 0; w < bone.mNumWeights; ++w)
        if (bone.mWeights[w].mWeight > 0)
            return true;
    return false;
}

std::map<int, unsigned> takeEndBones(const aiMesh& mesh, const AssimpNodeTree& tree,
                                     std::map<int, unsigned>& boneOfNode) {
    std::set<int> hasBoneChild;
    for (const auto& [node, b] : boneOfNode)
        for (int up = tree.parent(node); up >= 0; up = tree.parent(up))
            if (boneOfNode.contains(up))
                hasBoneChild.insert(up);
    std::map<int, unsigned> endOfParent;
    for (const auto& [node, b] : boneOfNode) {
        const int parent = tree.parent(node);
        if (parent < 0 || !boneOfNode.contains(parent) || hasBoneChild.contains(node) ||
            hasWeight(*mesh.mBones[b]))
            continue;
        if (std::string(tree.node(node).mName.C_Str()) ==
            std::string(tree.node(parent).mName.C_Str()) + "_end")
            endOfParent[parent] = b;
    }
    for (const auto& [parent, b] : endOfParent)
        boneOfNode.erase(tree.find(mesh.mBones[b]->mName.C_Str()));
    return endOfParent;
}

void keepOwnBones(const aiMesh& mesh, const Eigen::Affine3d& meshGlobal, const AssimpNodeTree& tree,
                  const std::set<std::string>& weightedAnywhere,
                  std::map<int, unsigned>& boneOfNode) {
    auto rootOf = [&](int node) {
        int root = node;
        for (int up = tree.parent(node); up >= 0; up = tree.parent(up))
            if (boneOfNode.contains(up))
                root = up;
        return root;
    };
    std::map<int, bool> here, anywhere;  // per root bone node
    for (const auto& [node, b] : boneOfNode) {
        const int root = rootOf(node);
        here[root] = here[root] || hasWeight(*mesh.mBones[b]);
        anywhere[root] = anywhere[root] || weightedAnywhere.contains(tree.node(node).mName.C_Str());
    }
    auto headOf = [&](int root) { return bindHead(*mesh.mBones[boneOfNode.at(root)], meshGlobal); };
    std::set<int> keptRoots;
    for (const auto& [root, weighted] : here)
        if (weighted)
            keptRoots.insert(root);
    if (keptRoots.empty())
        return;
    for (const auto& [root, weighted] : here)
        if (!weighted && !anywhere[root])
            for (int kept : std::set<int>(keptRoots))
                if ((headOf(root) - headOf(kept)).norm() <=
                    1e-9 * std::max(1.0, headOf(kept).norm()))
                    keptRoots.insert(root);
    std::map<int, unsigned> kept;
    for (const auto& [node, b] : boneOfNode)
        if (keptRoots.contains(rootOf(node)))
            kept.emplace(node, b);
    boneOfNode = std::move(kept);
}

// A number of a node's metadata (any numeric type), or nothing.
std::optional<double> metadataNumber(const aiMetadata& metadata, unsigned i) {
    const aiMetadataEntry& entry = metadata.mValues[i];
    if (entry.mData == nullptr)
        return std::nullopt;
    switch (entry.mType) {
        case AI_FLOAT:
            return *static_cast<const float*>(entry.mData);
        case AI_DOUBLE:
            return *static_cast<const double*>(entry.mData);
        case AI_INT32:
            return *static_cast<const std::int32_t*>(entry.mData);
        case AI_UINT64:
            return static_cast<double>(*static_cast<const std::uint64_t*>(entry.mData));
        default:
            return std::nullopt;
    }
}

}  // namespace

MeshBones meshBones(const aiMesh& mesh, const Eigen::Affine3d& meshGlobal,
                    const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere) {
    MeshBones bones;
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const int node = tree.find(mesh.mBones[b]->mName.C_Str());
        if (node < 0)
            bones.nodeless.push_back(b);
        else
            bones.boneOfNode[node] = b;
    }
    bones.endOfParent = takeEndBones(mesh, tree, bones.boneOfNode);
    keepOwnBones(mesh, meshGlobal, tree, weightedAnywhere, bones.boneOfNode);
    return bones;
}

std::optional<Vec3> tailMetadata(const aiNode& node) {
    if (node.mMetaData == nullptr)
        return std::nullopt;
    for (unsigned i = 0; i < node.mMetaData->mNumProperties; ++i) {
        const aiMetadataEntry& entry = node.mMetaData->mValues[i];
        if (std::string(node.mMetaData->mKeys[i].C_Str()) != kTailMetadataKey ||
            entry.mData == nullptr)
            continue;
        if (entry.mType == AI_AIVECTOR3D) {
            const Vec3 tail = fromAi(*static_cast<const aiVector3D*>(entry.mData));
            return tail.allFinite() ? std::optional<Vec3>(tail) : std::nullopt;
        }
        if (entry.mType != AI_AIMETADATA)
            return std::nullopt;
        const auto& list = *static_cast<const aiMetadata*>(entry.mData);
        if (list.mNumProperties != 3)
            return std::nullopt;
        Vec3 tail;
        for (unsigned k = 0; k < 3; ++k) {
            const std::optional<double> value = metadataNumber(list, k);
            if (!value || !std::isfinite(*value))
                return std::nullopt;
            tail[k] = *value;
        }
        return tail;
    }
    return std::nullopt;
}

std::optional<std::string> nameMetadata(const aiNode& node) {
    aiString name;
    if (node.mMetaData == nullptr || !node.mMetaData->Get(kNameMetadataKey, name) ||
        name.length == 0)
        return std::nullopt;
    return std::string(name.C_Str());
}

std::string meshName(const aiMesh& mesh, const aiNode& node) {
    for (const aiString* name : {&node.mName, &mesh.mName}) {
        std::string text = name->C_Str();
        // Assimp's COLLADA reader names nodes with no name after their mesh.
        if (!text.empty() && text != "RootNode" && text.find("$Assimp") == std::string::npos)
            return text;
    }
    return "part";
}

double clipRate(const std::set<double>& ticks, double ticksPerSecond) {
    for (double rate : {24.0, 25.0, 30.0, 48.0, 50.0, 60.0, 96.0, 100.0, 120.0, 240.0}) {
        bool onFrames = true;
        for (double t : ticks) {
            const double frame = t / ticksPerSecond * rate;
            onFrames = onFrames && std::abs(frame - std::round(frame)) <= 1e-4;
        }
        if (onFrames)
            return rate;
    }
    double fps = 24.0, previous = -1e300;
    for (double t : ticks) {
        while ((t - previous) / ticksPerSecond < 1.0 / fps && fps < 1e6)
            fps *= 2;
        previous = t;
    }
    return fps;
}

}  // namespace rigmesh
