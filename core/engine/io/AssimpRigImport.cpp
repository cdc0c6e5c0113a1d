#include "io/AssimpRigImport.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <optional>
#include <set>

#include "io/AssimpConversions.h"
#include "io/BoneTipHints.h"

namespace rigmesh {
namespace {

// Per aiBone index: its node index in the tree (-1 if none).
std::vector<int> boneNodes(const aiMesh& mesh, const AssimpNodeTree& tree) {
    std::vector<int> nodes;
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        nodes.push_back(tree.find(mesh.mBones[b]->mName.C_Str()));
    return nodes;
}

// World bind transform of a bone: meshGlobal * inverse(offset).
Eigen::Affine3d bindGlobal(const aiBone& bone, const Eigen::Affine3d& meshGlobal) {
    const Eigen::Matrix4d bind =
        meshGlobal.matrix() * fromAi(bone.mOffsetMatrix).matrix().inverse();
    return Eigen::Affine3d(bind);
}

double meshSize(const Part& part) {
    if (part.mesh.vertices.empty())
        return 1.0;
    Vec3 lo = part.mesh.vertices[0], hi = lo;
    for (const Vec3& v : part.mesh.vertices) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return std::max((hi - lo).norm(), 1e-9);
}

// Assimp 5.2.5's glTF exporter writes one skin for all meshes, so every
// mesh reads back with every part's bones: keep the bone trees (each root
// bone with its descendants) that weight this mesh, and the trees that weight
// no mesh but start at the same joint as a kept one (a part's root bones).
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
        bool weighted = false;
        for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights && !weighted; ++w)
            weighted = mesh.mBones[b]->mWeights[w].mWeight > 0;
        here[root] = here[root] || weighted;
        anywhere[root] = anywhere[root] || weightedAnywhere.contains(tree.node(node).mName.C_Str());
    }
    auto headOf = [&](int root) -> Vec3 {
        return bindGlobal(*mesh.mBones[boneOfNode.at(root)], meshGlobal).translation();
    };
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

// Our exporter's leaf tail (BoneTipHints.h) in the node's own frame, which
// Assimp reads into the node's metadata: from glTF extras as a nested list,
// from an FBX user property as a vector.
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

bool hasWeight(const aiBone& bone) {
    for (unsigned w = 0; w < bone.mNumWeights; ++w)
        if (bone.mWeights[w].mWeight > 0)
            return true;
    return false;
}

// End bones (our leafBones, Blender's FBX "Add Leaf Bones"): a bone named
// `<parent>_end` whose node is a child of its parent bone's node, with no
// weights and no bone below it. It only marks its parent's tail: taken out
// of `boneOfNode`, returned per parent node.
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

// The rotation of the space Blender's COLLADA tips are in: the armature, the
// nearest ancestor of `node` that is no bone.
Eigen::Matrix3d armatureRotation(int node, const AssimpNodeTree& tree,
                                 const std::map<int, unsigned>& boneOfNode) {
    int up = tree.parent(node);
    while (up >= 0 && boneOfNode.contains(up))
        up = tree.parent(up);
    return up < 0 ? Eigen::Matrix3d::Identity() : Eigen::Matrix3d(tree.restGlobal(up).linear());
}

}  // namespace

std::string importRig(const aiMesh& mesh, const Eigen::Affine3d& meshGlobal,
                      const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere,
                      const std::map<std::string, Vec3>& colladaTips, ImportedPart& imported) {
    Part& part = imported.part;
    const std::vector<int> nodes = boneNodes(mesh, tree);
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        if (nodes[b] < 0)
            return std::string("bone '") + mesh.mBones[b]->mName.C_Str() + "' has no node";
    std::map<int, unsigned> boneOfNode;
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        boneOfNode[nodes[b]] = b;
    const std::map<int, unsigned> endBones = takeEndBones(mesh, tree, boneOfNode);
    keepOwnBones(mesh, meshGlobal, tree, weightedAnywhere, boneOfNode);
    // Parent bone: nearest ancestor node that is a bone. Tree order is parent
    // first, so sorting by node index gives a parent-first bone order.
    std::vector<std::pair<int, unsigned>> order(boneOfNode.begin(), boneOfNode.end());
    std::map<unsigned, int> parentBone;
    std::map<unsigned, std::vector<unsigned>> childBones;
    for (const auto& [node, b] : order) {
        int up = tree.parent(node);
        while (up >= 0 && !boneOfNode.contains(up))
            up = tree.parent(up);
        parentBone[b] = up < 0 ? -1 : static_cast<int>(boneOfNode[up]);
        if (up >= 0)
            childBones[boneOfNode[up]].push_back(b);
    }
    auto head = [&](unsigned b) -> Vec3 {
        return bindGlobal(*mesh.mBones[b], meshGlobal).translation();
    };
    // Tails, most trusted first (SceneImport.h).
    auto tail = [&](unsigned b) -> Vec3 {
        if (!childBones[b].empty())
            return head(childBones[b].front());
        const int node = nodes[b];
        const std::string name = tree.node(node).mName.C_Str();
        if (const auto end = endBones.find(node); end != endBones.end())
            return head(end->second);
        if (const int tip = tree.find(name + "_end"); tip >= 0)  // older exports: a tip node
            return tree.restGlobal(tip).translation();
        const Eigen::Affine3d bind = bindGlobal(*mesh.mBones[b], meshGlobal);
        if (const std::optional<Vec3> local = tailMetadata(tree.node(node)))
            return bind * *local;
        if (const auto tip = colladaTips.find(name); tip != colladaTips.end())
            return head(b) + armatureRotation(node, tree, boneOfNode) * tip->second;
        // Blender's guess: along the bone node's +Y, as long as its parent.
        const double length = parentBone[b] >= 0
                                  ? (head(b) - head(static_cast<unsigned>(parentBone[b]))).norm()
                                  : 0.1 * meshSize(part);
        const Vec3 axis = bind.linear() * Vec3::UnitY();
        return head(b) + length * (axis.norm() > 0 ? Vec3(axis.normalized()) : Vec3::UnitY());
    };

    // Joints at the same place are one. Files store 32-bit floats and a
    // head comes from inverting a rotated bind matrix: 1e-5 of the size.
    const double tolerance = 1e-5 * meshSize(part);
    std::vector<std::pair<Vec3, JointId>> joints;
    auto jointAt = [&](const Vec3& p) {
        for (const auto& [q, id] : joints)
            if ((p - q).norm() <= tolerance)
                return id;
        const JointId id = part.skeleton.addJoint(p);
        joints.emplace_back(p, id);
        return id;
    };
    std::map<unsigned, BoneId> boneOfAiBone;
    for (const auto& [node, b] : order) {
        const JointId h = jointAt(head(b));
        const JointId t = jointAt(tail(b));
        if (h == t)
            return std::string("bone '") + mesh.mBones[b]->mName.C_Str() + "' has no length";
        boneOfAiBone[b] = part.skeleton.addBone(h, t);
        imported.boneNames.push_back(mesh.mBones[b]->mName.C_Str());
    }
    if (!order.empty())
        part.skeleton.setRoot(jointAt(head(order.front().second)));

    part.weights.perVertex.assign(mesh.mNumVertices, {});
    for (const auto& [node, b] : boneOfNode)
        for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights; ++w) {
            const aiVertexWeight& weight = mesh.mBones[b]->mWeights[w];
            if (weight.mVertexId < mesh.mNumVertices && weight.mWeight > 0)
                part.weights.perVertex[weight.mVertexId].emplace_back(boneOfAiBone[b],
                                                                      weight.mWeight);
        }
    bool unweighted = false;
    for (auto& list : part.weights.perVertex) {
        std::sort(list.begin(), list.end());
        // A file may weight one vertex twice by the same bone: one entry each.
        std::vector<std::pair<BoneId, double>> merged;
        for (const auto& entry : list)
            if (!merged.empty() && merged.back().first == entry.first)
                merged.back().second += entry.second;
            else
                merged.push_back(entry);
        list = std::move(merged);
        double sum = 0;
        for (const auto& [bone, w] : list)
            sum += w;
        unweighted = unweighted || list.empty();
        for (auto& entry : list)
            entry.second /= sum;
    }
    const std::vector<std::string> problems = part.skeleton.validate();
    if (!problems.empty())
        return "its skeleton is not usable: " + problems.front();
    if (unweighted)
        return "some vertices have no skin weights";
    return {};
}

std::optional<Clip> importClip(const aiAnimation& animation, const aiMesh& mesh,
                               const Eigen::Affine3d& meshGlobal, const AssimpNodeTree& tree,
                               const ImportedPart& imported) {
    const Part& part = imported.part;
    std::set<std::string> names(imported.boneNames.begin(), imported.boneNames.end());
    std::set<double> ticks;
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        const aiNodeAnim& channel = *animation.mChannels[c];
        if (!names.contains(channel.mNodeName.C_Str()))
            continue;
        for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
            ticks.insert(channel.mRotationKeys[k].mTime);
        for (unsigned k = 0; k < channel.mNumPositionKeys; ++k)
            ticks.insert(channel.mPositionKeys[k].mTime);
    }
    if (ticks.empty())
        return std::nullopt;
    const double perSecond = animation.mTicksPerSecond > 0 ? animation.mTicksPerSecond : 1.0;
    double fps = 24.0, previous = -1e300;
    for (double t : ticks) {
        while ((t - previous) / perSecond < 1.0 / fps && fps < 1e6)
            fps *= 2;
        previous = t;
    }
    Clip clip(fps);
    clip.interpolation = Interpolation::Linear;
    // Keys lie at 0 s or later (Clip.h): a clip that starts before 0 s is
    // moved as a whole to start there.
    const double start = std::min(0.0, *ticks.begin());

    const Skeleton& skeleton = part.skeleton;
    std::map<std::string, unsigned> aiBoneByName;
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        aiBoneByName[mesh.mBones[b]->mName.C_Str()] = b;
    const std::vector<BoneId> hierarchy = skeleton.bonesInHierarchyOrder();
    for (double t : ticks) {
        const std::vector<Eigen::Affine3d> globals = tree.animatedGlobals(animation, t);
        // Per bone (Pose.h: keyed by its tail joint), its world rotation
        // (rest -> posed) relative to its parent bone's; root bones turn
        // about the root, which the first of them places.
        std::map<JointId, Eigen::Quaterniond> world;
        Pose pose;
        bool rootPlaced = false;
        for (BoneId id : hierarchy) {
            const Bone& bone = skeleton.bone(id);
            const int index = skeleton.indexOfBone(id);
            const unsigned b = aiBoneByName[imported.boneNames[static_cast<std::size_t>(index)]];
            const int node = tree.find(imported.boneNames[static_cast<std::size_t>(index)]);
            const Eigen::Affine3d skin = globals[static_cast<std::size_t>(node)] *
                                         fromAi(mesh.mBones[b]->mOffsetMatrix) *
                                         meshGlobal.inverse();
            const Eigen::Quaterniond rotation = Eigen::Quaterniond(skin.rotation()).normalized();
            world[bone.tail] = rotation;
            const std::optional<BoneId> parent = skeleton.parentBone(id);
            if (!parent) {
                pose.setRotation(bone.tail, rotation);
                if (!rootPlaced) {
                    const Vec3 h = skeleton.joint(bone.head).position;
                    pose.rootTranslation = skin.translation() - h + rotation * h;
                    rootPlaced = true;
                }
            } else {
                const Eigen::Quaterniond up = world[skeleton.bone(*parent).tail];
                pose.setRotation(bone.tail, (up.conjugate() * rotation).normalized());
            }
        }
        clip.setKey((t - start) / perSecond, pose);
    }
    return clip;
}

}  // namespace rigmesh
