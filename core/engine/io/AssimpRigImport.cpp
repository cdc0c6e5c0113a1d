#include "io/AssimpRigImport.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <optional>
#include <set>

#include "io/AssimpBoneHints.h"
#include "io/AssimpConversions.h"
#include "io/BoneTails.h"

namespace rigmesh {
namespace {

// World bind transform of a bone: meshGlobal * inverse(offset).
Eigen::Affine3d bindGlobal(const aiBone& bone, const Eigen::Affine3d& meshGlobal) {
    const Eigen::Matrix4d bind =
        meshGlobal.matrix() * fromAi(bone.mOffsetMatrix).matrix().inverse();
    return Eigen::Affine3d(bind);
}

double diagonal(const std::vector<Vec3>& points) {
    if (points.empty())
        return 1.0;
    Vec3 lo = points[0], hi = lo;
    for (const Vec3& v : points) {
        lo = lo.cwiseMin(v);
        hi = hi.cwiseMax(v);
    }
    return std::max((hi - lo).norm(), 1e-9);
}

// Every bone the group's meshes name, by node (nodeless ones by name), with
// its world bind transform; then the nodes between two of them (Blender
// makes those bones too), their binds carried up from a bone below through
// the nodes' rest transforms.
struct CollectedBones {
    std::map<int, Eigen::Affine3d> byNode;
    std::map<std::string, Eigen::Affine3d> nodeless;
    std::map<int, Vec3> endBoneHeads;  // per bone node: its end bone's head
};

// The ancestors of `bones` that the file animates, up to the first one it
// does not. Neither the scene root nor its children: a child of the root
// is the armature object (Blender's FBX keys its armature, and its
// importer makes no bone of it), while a game format's unweighted root
// bones hang lower (Half-Life's under <MDL_bones>).
std::set<int> animatedAncestors(const std::set<int>& bones, const AssimpNodeTree& tree,
                                const std::set<std::string>& animated) {
    std::set<int> out;
    for (int node : bones)
        for (int up = tree.parent(node); up > 0 && tree.parent(up) > 0 && !bones.contains(up) &&
                                         animated.contains(tree.node(up).mName.C_Str());
             up = tree.parent(up))
            out.insert(up);
    return out;
}

CollectedBones collectBones(const aiScene& scene, const std::vector<SkinnedMesh>& group,
                            const AssimpNodeTree& tree,
                            const std::set<std::string>& weightedAnywhere, const RigHints& hints) {
    CollectedBones out;
    for (const SkinnedMesh& item : group) {
        const aiMesh& mesh = *scene.mMeshes[item.mesh];
        const MeshBones bones = meshBones(mesh, item.global, tree, weightedAnywhere);
        for (const auto& [node, b] : bones.boneOfNode)
            out.byNode.emplace(node, bindGlobal(*mesh.mBones[b], item.global));
        for (const auto& [node, b] : bones.endOfParent)
            out.endBoneHeads.emplace(node, bindGlobal(*mesh.mBones[b], item.global).translation());
        for (unsigned b : bones.nodeless)
            out.nodeless.emplace(mesh.mBones[b]->mName.C_Str(),
                                 bindGlobal(*mesh.mBones[b], item.global));
    }
    // Animated ancestors (groupBySkeleton) and nodes between bones, nearest
    // the bone below first.
    std::set<int> named;
    for (const auto& [node, bind] : out.byNode)
        named.insert(node);
    const std::set<int> ancestors = animatedAncestors(named, tree, hints.animatedNodes);
    std::map<int, Eigen::Affine3d> between;
    for (const auto& [node, bind] : out.byNode) {
        std::vector<int> path;
        int up = tree.parent(node);
        while (up >= 0 && !out.byNode.contains(up)) {
            path.push_back(up);
            if (ancestors.contains(up) && !ancestors.contains(tree.parent(up)) &&
                !out.byNode.contains(tree.parent(up)))
                break;  // the topmost animated ancestor
            up = tree.parent(up);
        }
        if (up < 0 || path.empty() || (!out.byNode.contains(up) && !ancestors.contains(up)))
            continue;
        const Eigen::Affine3d toRest = bind * tree.restGlobal(node).inverse();
        for (int helper : path)
            between.emplace(helper, toRest * tree.restGlobal(helper));
    }
    out.byNode.insert(between.begin(), between.end());
    return out;
}

// Rotation (scale taken out) of a bind transform, and whether it is proper.
Eigen::Matrix3d bindAxes(const Eigen::Affine3d& bind) {
    return bind.rotation();
}

struct PartBone {
    int node = -1;
    std::string name;
    Eigen::Affine3d bind;
    int parent = -1;
};

std::vector<PartBone> orderedBones(const CollectedBones& collected, const AssimpNodeTree& tree) {
    std::vector<PartBone> bones;
    std::map<int, int> indexOfNode;
    for (const auto& [node, bind] : collected.byNode) {  // tree order: parents first
        PartBone bone{node, tree.node(node).mName.C_Str(), bind, -1};
        for (int up = tree.parent(node); up >= 0; up = tree.parent(up))
            if (const auto it = indexOfNode.find(up); it != indexOfNode.end()) {
                bone.parent = it->second;
                break;
            }
        indexOfNode[node] = static_cast<int>(bones.size());
        bones.push_back(bone);
    }
    for (const auto& [name, bind] : collected.nodeless)
        bones.push_back({-1, name, bind, -1});
    return bones;
}

// The tail a file states for a bone (TailBone::statedTail): our exact tail
// (glTF and FBX metadata, our COLLADA profile's tip), its end bone's head, a
// `<bone>_end` node (our exports before leaf bones), or Blender's COLLADA
// tip. Ours come first: where a tail lies on the surface, the end bone and
// Blender's tip show it a little inside (ExportBoneNode::shownTail).
std::optional<Vec3> statedTail(const PartBone& bone, const CollectedBones& collected,
                               const AssimpNodeTree& tree, const RigHints& hints) {
    if (bone.node < 0)
        return std::nullopt;
    auto fromTip = [&](const Vec3& tip) {
        return Vec3(bone.bind.translation() +
                    armatureRotation(bone.node, tree, collected.byNode) * tip);
    };
    if (const std::optional<Vec3> local = tailMetadata(tree.node(bone.node)))
        return bone.bind * *local;
    if (const auto tip = hints.colladaExactTips.find(bone.name);
        tip != hints.colladaExactTips.end())
        return fromTip(tip->second);
    if (const auto end = collected.endBoneHeads.find(bone.node);
        end != collected.endBoneHeads.end())
        return end->second;
    if (const int tip = tree.find(bone.name + "_end"); tip >= 0 && !collected.byNode.contains(tip))
        return tree.restGlobal(tip).translation();
    if (const auto tip = hints.colladaTips.find(bone.name); tip != hints.colladaTips.end())
        return fromTip(tip->second);
    return std::nullopt;
}

}  // namespace

TriMesh worldMesh(const aiMesh& mesh, const Eigen::Affine3d& global) {
    TriMesh out;
    out.vertices.reserve(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        out.vertices.push_back(global * fromAi(mesh.mVertices[v]));
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices == 3 && face.mIndices[0] != face.mIndices[1] &&
            face.mIndices[1] != face.mIndices[2] && face.mIndices[0] != face.mIndices[2])
            out.faces.push_back({static_cast<int>(face.mIndices[0]),
                                 static_cast<int>(face.mIndices[1]),
                                 static_cast<int>(face.mIndices[2])});
    }
    return out;
}

std::vector<std::vector<SkinnedMesh>> groupBySkeleton(const aiScene& scene,
                                                      const AssimpNodeTree& tree,
                                                      const std::vector<SkinnedMesh>& meshes,
                                                      const std::set<std::string>& weightedAnywhere,
                                                      const RigHints& hints) {
    std::vector<std::set<int>> nodesOf;
    std::set<int> allBones;
    for (const SkinnedMesh& item : meshes) {
        std::set<int> nodes;
        for (const auto& [node, b] :
             meshBones(*scene.mMeshes[item.mesh], item.global, tree, weightedAnywhere).boneOfNode)
            nodes.insert(node);
        allBones.insert(nodes.begin(), nodes.end());
        nodesOf.push_back(std::move(nodes));
    }
    const std::set<int> ancestors = animatedAncestors(allBones, tree, hints.animatedNodes);
    allBones.insert(ancestors.begin(), ancestors.end());
    auto topOf = [&](int node) {
        int top = node;
        for (int up = tree.parent(node); up >= 0; up = tree.parent(up))
            if (allBones.contains(up))
                top = up;
        return top;
    };
    std::vector<std::size_t> groupOf(meshes.size());
    std::iota(groupOf.begin(), groupOf.end(), 0);
    std::map<int, std::size_t> meshOfTop;
    for (std::size_t m = 0; m < meshes.size(); ++m)
        for (int node : nodesOf[m]) {
            const auto [it, added] = meshOfTop.emplace(topOf(node), m);
            if (!added) {  // the later group joins the earlier one
                const std::size_t from = groupOf[m], to = groupOf[it->second];
                for (std::size_t& g : groupOf)
                    if (g == from)
                        g = to;
            }
        }
    std::vector<std::vector<SkinnedMesh>> groups;
    std::map<std::size_t, std::size_t> indexOfGroup;
    for (std::size_t m = 0; m < meshes.size(); ++m) {
        const auto [it, added] = indexOfGroup.emplace(groupOf[m], groups.size());
        if (added)
            groups.emplace_back();
        groups[it->second].push_back(meshes[m]);
    }
    return groups;
}

std::string importRig(const aiScene& scene, const std::vector<SkinnedMesh>& group,
                      const AssimpNodeTree& tree, const std::set<std::string>& weightedAnywhere,
                      const RigHints& hints, ImportedPart& imported, ImportedBones& result) {
    Part& part = imported.part;
    // The meshes, one after the other.
    std::vector<int> firstVertex;
    for (const SkinnedMesh& item : group) {
        const aiMesh& mesh = *scene.mMeshes[item.mesh];
        const TriMesh piece = worldMesh(mesh, item.global);
        firstVertex.push_back(part.mesh.vertexCount());
        for (const auto& face : piece.faces)
            part.mesh.faces.push_back({face[0] + firstVertex.back(), face[1] + firstVertex.back(),
                                       face[2] + firstVertex.back()});
        part.mesh.vertices.insert(part.mesh.vertices.end(), piece.vertices.begin(),
                                  piece.vertices.end());
        if (group.size() > 1)
            part.meshPieces.push_back(
                {meshName(mesh, tree.node(item.node)), piece.vertexCount(), piece.faceCount()});
    }

    const CollectedBones collected = collectBones(scene, group, tree, weightedAnywhere, hints);
    const std::vector<PartBone> bones = orderedBones(collected, tree);
    if (bones.empty())
        return "it has no bones";
    std::map<std::string, int> indexOfName;
    for (std::size_t b = 0; b < bones.size(); ++b)
        indexOfName.emplace(bones[b].name, static_cast<int>(b));

    // Weights by bone index, per vertex of the whole mesh.
    std::vector<std::vector<std::pair<int, double>>> weights(part.mesh.vertices.size());
    for (std::size_t m = 0; m < group.size(); ++m) {
        const aiMesh& mesh = *scene.mMeshes[group[m].mesh];
        const MeshBones own = meshBones(mesh, group[m].global, tree, weightedAnywhere);
        std::vector<unsigned> used = own.nodeless;
        for (const auto& [node, b] : own.boneOfNode)
            used.push_back(b);
        for (unsigned b : used) {
            const int bone = indexOfName.at(mesh.mBones[b]->mName.C_Str());
            for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights; ++w) {
                const aiVertexWeight& weight = mesh.mBones[b]->mWeights[w];
                if (weight.mVertexId < mesh.mNumVertices && weight.mWeight > 0)
                    weights[static_cast<std::size_t>(firstVertex[m]) + weight.mVertexId]
                        .emplace_back(bone, weight.mWeight);
            }
        }
    }
    std::vector<int> dominant(weights.size(), -1);
    bool unweighted = false;
    for (std::size_t v = 0; v < weights.size(); ++v) {
        auto& list = weights[v];
        std::sort(list.begin(), list.end());
        // A file may weight one vertex twice by the same bone: one entry each.
        std::vector<std::pair<int, double>> merged;
        for (const auto& entry : list)
            if (!merged.empty() && merged.back().first == entry.first)
                merged.back().second += entry.second;
            else
                merged.push_back(entry);
        list = std::move(merged);
        double sum = 0, best = 0;
        for (const auto& [bone, w] : list) {
            sum += w;
            if (w > best) {
                best = w;
                dominant[v] = bone;
            }
        }
        unweighted = unweighted || list.empty();
        for (auto& entry : list)
            entry.second /= sum;
    }

    // Tails and connections (BoneTails.h).
    std::vector<TailBone> tailBones;
    for (const PartBone& bone : bones) {
        TailBone t;
        t.head = bone.bind.translation();
        t.axes = bindAxes(bone.bind);
        t.parent = bone.parent;
        t.statedTail = statedTail(bone, collected, tree, hints);
        if (const auto flag = hints.colladaConnections.find(bone.name);
            flag != hints.colladaConnections.end() && bone.parent >= 0)
            t.connectFlag = flag->second;
        tailBones.push_back(t);
    }
    const double size = diagonal(part.mesh.vertices);
    const BoneTailsResult tails = guessBoneTails(tailBones, part.mesh, dominant, size);

    // Joints: a connected bone's head is its parent's tail joint; the heads of
    // a parent's disconnected children at one place share a joint attached
    // to it; root bones at the first one's head share the root, others at
    // one place share a joint of a further root chain.
    const double tolerance = 1e-5 * size;
    std::vector<JointId> tailJoint(bones.size(), kNoJoint);
    std::map<int, std::vector<std::pair<Vec3, JointId>>> chainHeads;  // per parent (-1: roots)
    auto chainHead = [&](int parent, const Vec3& at) {
        auto& heads = chainHeads[parent];
        for (const auto& [p, joint] : heads)
            if ((p - at).norm() <= tolerance)
                return joint;
        const JointId joint = part.skeleton.addJoint(at);
        if (!(parent < 0 && heads.empty()))  // the first root head is the root
            part.skeleton.attach(joint, parent < 0 ? kNoBone : static_cast<BoneId>(parent));
        heads.emplace_back(at, joint);
        return joint;
    };
    for (std::size_t b = 0; b < bones.size(); ++b) {
        const int parent = bones[b].parent;
        const JointId head = parent >= 0 && tails.connected[b]
                                 ? tailJoint[static_cast<std::size_t>(parent)]
                                 : chainHead(parent, tailBones[b].head);
        tailJoint[b] = part.skeleton.addJoint(tails.tails[b]);
        // Bone ids follow the bone index (ids from 0, in this order).
        part.skeleton.addBone(head, tailJoint[b]);
        // The node's name, or the bone's own that our exporter kept beside it.
        std::optional<std::string> ownName =
            bones[b].node >= 0 ? nameMetadata(tree.node(bones[b].node)) : std::nullopt;
        if (const auto kept = hints.colladaNames.find(bones[b].name);
            kept != hints.colladaNames.end())
            ownName = kept->second;
        imported.boneNames.push_back(ownName ? *ownName : bones[b].name);
        const Eigen::Quaterniond frame(bindAxes(bones[b].bind));
        if (bindAxes(bones[b].bind).determinant() > 0 && frame.coeffs().allFinite())
            part.boneFrames.emplace(static_cast<BoneId>(b), frame.normalized());
        result.nodes.push_back(bones[b].node);
        result.binds.push_back(bones[b].bind);
    }

    part.weights.perVertex.assign(weights.size(), {});
    for (std::size_t v = 0; v < weights.size(); ++v)
        for (const auto& [bone, w] : weights[v])
            part.weights.perVertex[v].emplace_back(static_cast<BoneId>(bone), w);
    const std::vector<Message> problems = part.skeleton.validate();
    if (!problems.empty())
        return "its skeleton is not usable: " + englishText(problems.front());
    if (unweighted)
        return "some vertices have no skin weights";
    return {};
}

std::optional<Clip> importClip(const aiAnimation& animation, const AssimpNodeTree& tree,
                               const ImportedPart& imported, const ImportedBones& bones) {
    const Skeleton& skeleton = imported.part.skeleton;
    // The nodes that move the part: its bones' and their ancestors.
    std::set<std::string> moving, boneNodes;
    for (int node : bones.nodes) {
        if (node >= 0)
            boneNodes.insert(tree.node(node).mName.C_Str());
        for (int up = node; up >= 0; up = tree.parent(up))
            moving.insert(tree.node(up).mName.C_Str());
    }
    std::set<double> ticks;
    bool movesBones = false;
    for (unsigned c = 0; c < animation.mNumChannels; ++c) {
        const aiNodeAnim& channel = *animation.mChannels[c];
        if (!moving.contains(channel.mNodeName.C_Str()))
            continue;
        movesBones = movesBones || boneNodes.contains(channel.mNodeName.C_Str());
        for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
            ticks.insert(channel.mRotationKeys[k].mTime);
        for (unsigned k = 0; k < channel.mNumPositionKeys; ++k)
            ticks.insert(channel.mPositionKeys[k].mTime);
    }
    if (ticks.empty() || !movesBones)
        return std::nullopt;
    const double perSecond = animation.mTicksPerSecond > 0 ? animation.mTicksPerSecond : 1.0;
    Clip clip(clipRate(ticks, perSecond));
    clip.interpolation = Interpolation::Linear;
    // Keys lie at 0 s or later (Clip.h): a clip that starts before 0 s is
    // moved as a whole to start there.
    const double start = std::min(0.0, *ticks.begin());

    const std::vector<BoneId> hierarchy = skeleton.bonesInHierarchyOrder();
    for (double t : ticks) {
        const std::vector<Eigen::Affine3d> globals = tree.animatedGlobals(animation, t);
        // Per bone (Pose.h: keyed by its tail joint), its world rotation
        // (rest -> posed) relative to its parent bone's; root bones turn
        // about the root, which the first of them places.
        std::map<BoneId, Eigen::Quaterniond> world;
        Pose pose;
        bool rootPlaced = false;
        for (BoneId id : hierarchy) {
            const Bone& bone = skeleton.bone(id);
            const auto index = static_cast<std::size_t>(skeleton.indexOfBone(id));
            const int node = bones.nodes[index];
            const Eigen::Affine3d skin =
                node >= 0 ? Eigen::Affine3d(globals[static_cast<std::size_t>(node)] *
                                            bones.binds[index].inverse())
                          : Eigen::Affine3d::Identity();
            const Eigen::Quaterniond rotation = Eigen::Quaterniond(skin.rotation()).normalized();
            world[id] = rotation;
            const std::optional<BoneId> parent = skeleton.parentBone(id);
            if (!parent) {
                pose.setRotation(bone.tail, rotation);
                if (!rootPlaced && bone.head == skeleton.root()) {
                    const Vec3 h = skeleton.joint(bone.head).position;
                    pose.rootTranslation = skin.translation() - h + rotation * h;
                    rootPlaced = true;
                }
            } else {
                pose.setRotation(bone.tail, (world[*parent].conjugate() * rotation).normalized());
            }
        }
        clip.setKey((t - start) / perSecond, pose);
    }
    return clip;
}

}  // namespace rigmesh
