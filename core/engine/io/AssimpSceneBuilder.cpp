#include "io/AssimpSceneBuilder.h"

#include <assimp/material.h>
#include <assimp/metadata.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include "base/Error.h"
#include "io/AssimpAnimationBuilder.h"
#include "io/AssimpConversions.h"
#include "io/ExportRig.h"
#include "io/InfluenceLimit.h"
#include "mesh/VertexNormals.h"
#include "pose/Skinning.h"

namespace rigmesh {
namespace {

// Part names made safe and unique (docs/EXCHANGE.md rule 2: every node name unique).
std::vector<std::string> uniquePartNames(const std::vector<ExportPart>& parts) {
    std::vector<std::string> names;
    std::set<std::string> used = {"RootNode", "Armature"};
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::string wanted =
            sanitizedName(parts[i].name.empty() ? parts[i].part->name : parts[i].name);
        std::string name = wanted;
        for (int n = 2; used.contains(name); ++n)
            name = wanted + "_" + std::to_string(n);
        used.insert(name);
        names.push_back(name);
    }
    return names;
}

// `wanted`, or `wanted_2`, `wanted_3`, ...: the first not in `used`, which
// then holds it.
std::string uniqueName(const std::string& wanted, std::set<std::string>& used) {
    std::string name = wanted;
    for (int n = 2; used.contains(name); ++n)
        name = wanted + "_" + std::to_string(n);
    used.insert(name);
    return name;
}

// The clips of every part by animation name, in order of first appearance:
// clips of several parts with one name are one animation. A part
// with two clips of one name (not made by the studio) gets "<name>_2" for
// the second.
struct AnimationGroups {
    struct Member {
        const Clip* clip;
        std::size_t rig;
    };
    std::vector<std::pair<std::string, std::vector<Member>>> groups;

    void add(const std::string& name, Member member) {
        for (int n = 1;; ++n) {
            const std::string candidate = n == 1 ? name : name + "_" + std::to_string(n);
            auto group = std::find_if(groups.begin(), groups.end(),
                                      [&](const auto& g) { return g.first == candidate; });
            if (group == groups.end()) {
                groups.push_back({candidate, {member}});
                return;
            }
            if (std::none_of(group->second.begin(), group->second.end(),
                             [&](const Member& m) { return m.rig == member.rig; })) {
                group->second.push_back(member);
                return;
            }
        }
    }
};

// docs/EXCHANGE.md rule 2: every node name unique. Kept bone names (an import's) may
// meet a part's or another part's bone's: `_2`, `_3`, ... appended; an end
// bone's name (`<bone>_end`) is taken too.
void makeBoneNamesUnique(ExportRig& rig, std::set<std::string>& used) {
    for (ExportBoneNode& node : rig.nodes) {
        std::string name = node.name;
        for (int n = 2; used.contains(name) || used.contains(name + "_end"); ++n)
            name = node.name + "_" + std::to_string(n);
        if (name != node.name)
            node.renamedFrom = node.name;
        node.name = name;
        used.insert(name);
        used.insert(name + "_end");
    }
}

aiNode* newNode(const std::string& name, const Vec3& translation,
                const Eigen::Quaterniond& rotation) {
    auto* node = new aiNode(name);
    node->mTransformation = rigidMatrix(translation, rotation);
    return node;
}

void setChildren(aiNode* parent, const std::vector<aiNode*>& children) {
    if (children.empty())
        return;
    parent->mNumChildren = static_cast<unsigned>(children.size());
    parent->mChildren = new aiNode*[children.size()];
    for (std::size_t i = 0; i < children.size(); ++i) {
        parent->mChildren[i] = children[i];
        children[i]->mParent = parent;
    }
}

// One node per bone at its head, its +Y along the bone, parented by the bone
// hierarchy, nodes in the bind pose
// (docs/EXCHANGE.md rule 6); with `leafBones`, an end node under each leaf.
std::vector<aiNode*> boneNodes(const ExportRig& rig, bool leafBones) {
    std::vector<aiNode*> nodes;
    std::vector<std::vector<aiNode*>> children(rig.nodes.size());
    for (const ExportBoneNode& n : rig.nodes)
        nodes.push_back(newNode(n.name, n.restTranslation, n.restRotation));
    std::vector<aiNode*> roots;
    for (std::size_t i = 0; i < rig.nodes.size(); ++i) {
        const int parent = rig.nodes[i].parent;
        (parent < 0 ? roots : children[static_cast<std::size_t>(parent)]).push_back(nodes[i]);
        if (leafBones && rig.nodes[i].leaf) {  // at the leaf's tail, pointing back (ExportRig.h)
            const ExportBoneNode end = endBoneOf(rig.nodes[i]);
            children[i].push_back(newNode(end.name, end.restTranslation, end.restRotation));
        }
    }
    for (std::size_t i = 0; i < nodes.size(); ++i)
        setChildren(nodes[i], children[i]);
    return roots;
}

// Skin weights cut to the format's influences (docs/EXCHANGE.md rule 9), one
// aiBone per bone node named as the node (rule 2), offset = inverse bind matrix.
// End bones (leafBones) are joints without weights, so importers make bones
// of them.
void addBones(aiMesh* mesh, const Part& part, const ExportRig& rig, int maxInfluences,
              bool leafBones) {
    // Bone id -> position in skeleton.bones() -> the bone's node.
    const BoneIndexTable positionOf(part.skeleton);
    SkinWeights remapped;
    remapped.perVertex.resize(part.mesh.vertices.size());
    for (std::size_t v = 0; v < part.weights.perVertex.size(); ++v)
        for (const auto& [bone, w] : part.weights.perVertex[v]) {
            const int position = positionOf[bone];
            if (position >= 0 && position < static_cast<int>(rig.nodeOfBone.size()) &&
                rig.nodeOfBone[position] >= 0)
                remapped.perVertex[v].emplace_back(rig.nodeOfBone[position], w);
        }
    const SkinWeights limited = limitInfluences(remapped, maxInfluences);

    std::vector<std::vector<aiVertexWeight>> perNode(rig.nodes.size());
    for (std::size_t v = 0; v < limited.perVertex.size(); ++v) {
        if (limited.perVertex[v].empty()) {  // unweighted: follows the root bone
            perNode[0].emplace_back(static_cast<unsigned>(v), 1.0f);
            continue;
        }
        for (const auto& [node, w] : limited.perVertex[v])
            perNode[static_cast<std::size_t>(node)].emplace_back(static_cast<unsigned>(v),
                                                                 static_cast<float>(w));
    }
    std::vector<aiBone*> bones;
    for (std::size_t i = 0; i < rig.nodes.size(); ++i) {
        const ExportBoneNode& node = rig.nodes[i];
        auto* bone = new aiBone;
        bone->mName = aiString(node.name);
        bone->mOffsetMatrix = toAi(node.inverseBind());
        bone->mNumWeights = static_cast<unsigned>(perNode[i].size());
        if (!perNode[i].empty()) {
            bone->mWeights = new aiVertexWeight[perNode[i].size()];
            std::copy(perNode[i].begin(), perNode[i].end(), bone->mWeights);
        }
        bones.push_back(bone);
        if (leafBones && node.leaf) {
            const ExportBoneNode endNode = endBoneOf(node);
            auto* end = new aiBone;
            end->mName = aiString(endNode.name);
            end->mOffsetMatrix = toAi(endNode.inverseBind());
            bones.push_back(end);
        }
    }
    mesh->mNumBones = static_cast<unsigned>(bones.size());
    mesh->mBones = new aiBone*[bones.size()];
    std::copy(bones.begin(), bones.end(), mesh->mBones);
}

aiMesh* makeMesh(const ExportPart& item, const std::string& name, ExportFormat format,
                 const ExportOptions& options) {
    const Part& part = *item.part;
    TriMesh mesh = part.mesh;
    // A part without a skeleton (imported unrigged) has only its rest pose.
    if (format == ExportFormat::Obj && !options.restPose && part.skeleton.jointCount() > 0)
        mesh = posePart(part, item.pose, SkinningOptions{options.skinning}).mesh;
    const std::vector<Vec3> normals = vertexNormals(mesh);
    const Eigen::Matrix3d rotation = item.placement.rotation();

    auto* out = new aiMesh;
    out->mName = aiString(name);
    out->mPrimitiveTypes = aiPrimitiveType_TRIANGLE;
    out->mMaterialIndex = 0;
    out->mNumVertices = static_cast<unsigned>(mesh.vertices.size());
    out->mVertices = new aiVector3D[mesh.vertices.size()];
    out->mNormals = new aiVector3D[mesh.vertices.size()];
    for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
        out->mVertices[v] = toAi(Vec3(options.unitScale * (item.placement * mesh.vertices[v])));
        out->mNormals[v] = toAi(Vec3((rotation * normals[v]).normalized()));
    }
    out->mNumFaces = static_cast<unsigned>(mesh.faces.size());
    out->mFaces = new aiFace[mesh.faces.size()];
    for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
        aiFace& face = out->mFaces[f];
        face.mNumIndices = 3;
        face.mIndices = new unsigned[3];
        for (int k = 0; k < 3; ++k)
            face.mIndices[k] = static_cast<unsigned>(mesh.faces[f][static_cast<std::size_t>(k)]);
    }
    return out;
}

// docs/EXCHANGE.md rule 3: at least one material, or fbx and collada segfault.
aiMaterial* makeMaterial() {
    auto* material = new aiMaterial;
    const aiString name("rigmesh_material");
    material->AddProperty(&name, AI_MATKEY_NAME);
    const aiColor3D grey(0.8f, 0.8f, 0.8f);
    material->AddProperty(&grey, 1, AI_MATKEY_COLOR_DIFFUSE);
    return material;
}

// The meshes a part is written as: its pieces (a shared skeleton's meshes,
// Part::meshPieces), each with its own vertices, faces and weights, or the
// whole part. Named after each piece (made unique), else `name`.
struct PieceMesh {
    Part part;  // the piece's surface and weights (the rig stays the part's)
    std::string name;
};

std::vector<PieceMesh> piecesOf(const Part& part, const std::string& name,
                                std::set<std::string>& used) {
    if (part.meshPieces.size() < 2)
        return {};
    std::vector<PieceMesh> pieces;
    int firstVertex = 0, firstFace = 0;
    for (const PartMeshPiece& piece : part.meshPieces) {
        PieceMesh out;
        out.part.name = part.name;
        out.part.skeleton = part.skeleton;
        out.name = uniqueName(sanitizedName(piece.name.empty() ? name : piece.name), used);
        out.part.mesh.vertices.assign(part.mesh.vertices.begin() + firstVertex,
                                      part.mesh.vertices.begin() + firstVertex + piece.vertexCount);
        for (int f = firstFace; f < firstFace + piece.faceCount; ++f)
            out.part.mesh.faces.push_back({part.mesh.faces[f][0] - firstVertex,
                                           part.mesh.faces[f][1] - firstVertex,
                                           part.mesh.faces[f][2] - firstVertex});
        if (!part.weights.perVertex.empty())
            out.part.weights.perVertex.assign(
                part.weights.perVertex.begin() + firstVertex,
                part.weights.perVertex.begin() + firstVertex + piece.vertexCount);
        firstVertex += piece.vertexCount;
        firstFace += piece.faceCount;
        pieces.push_back(std::move(out));
    }
    return pieces;
}

void checkPart(const ExportPart& item, bool rigged) {
    if (item.part == nullptr)
        throw std::logic_error("cannot export: a part is missing");
    const Part& part = *item.part;
    if (part.mesh.vertices.empty() || part.mesh.faces.empty())
        throw Error(MessageId::ExportPartWithoutSurface, part.name);
    if (rigged && part.weights.perVertex.size() != part.mesh.vertices.size())
        throw Error(MessageId::ExportWeightsMismatch, part.name);
}

}  // namespace

std::vector<ExportRig> buildAssimpScene(aiScene& scene, const std::vector<ExportPart>& parts,
                                        const Clip* clip, ExportFormat format,
                                        const ExportOptions& options) {
    if (parts.empty())
        throw Error(MessageId::ExportNoPart);
    const bool rigged = isRiggedFormat(format);
    for (const ExportPart& item : parts)
        checkPart(item, rigged);
    if (!(options.unitScale > 0))
        throw Error(MessageId::ExportUnitScaleNotPositive);
    const std::vector<std::string> names = uniquePartNames(parts);
    std::set<std::string> usedNames(names.begin(), names.end());
    usedNames.insert({"RootNode", "Armature"});
    const int influences = effectiveInfluenceLimit(format, options.maxInfluences);

    // docs/EXCHANGE.md rules 1 and 7: identity root; meshes on child
    // nodes. One armature and mesh per part: each part's root bones under
    // its own node `<part>_armature`. In FBX that node also holds the part's
    // mesh node, as Blender's own FBX files do (measured with Blender 3.4.1
    // on the camel: with the mesh nodes beside the armatures, every other
    // mesh came in unbound); in glTF the mesh node stays a scene root and
    // GltfSkins.h gives each mesh its own skin. COLLADA keeps every bone
    // under one `Armature` beside the mesh nodes (docs/EXCHANGE.md rule 12): Blender's
    // COLLADA importer binds every mesh to the first armature anyway and
    // leaves the others empty.
    scene.mRootNode = new aiNode("RootNode");
    std::vector<aiNode*> rootChildren, armatureChildren;
    std::vector<aiAnimation*> animations;
    std::vector<ExportRig> rigs;
    AnimationGroups animationGroups;
    // One mesh node per piece of a part (one for a part without pieces). The
    // scene owns every mesh from the start (null until made), so none leaks
    // when a later step throws.
    std::vector<std::vector<PieceMesh>> piecesOfPart;
    std::size_t meshCount = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        piecesOfPart.push_back(piecesOf(*parts[i].part, names[i], usedNames));
        meshCount += std::max<std::size_t>(1, piecesOfPart.back().size());
    }
    scene.mNumMeshes = static_cast<unsigned>(meshCount);
    scene.mMeshes = new aiMesh* [meshCount] {};
    unsigned nextMesh = 0;
    for (std::size_t i = 0; i < parts.size(); ++i) {
        const std::vector<PieceMesh>& pieces = piecesOfPart[i];
        std::vector<ExportPart> items;
        std::vector<std::string> meshNames;
        for (const PieceMesh& piece : pieces) {
            items.push_back(parts[i]);
            items.back().part = &piece.part;
            meshNames.push_back(piece.name);
        }
        if (pieces.empty()) {
            items.push_back(parts[i]);
            meshNames.push_back(names[i]);
        }
        std::vector<aiNode*> meshNodes;
        const unsigned firstMesh = nextMesh;
        for (std::size_t k = 0; k < items.size(); ++k) {
            scene.mMeshes[nextMesh] = makeMesh(items[k], meshNames[k], format, options);
            aiNode* meshNode = new aiNode(meshNames[k]);
            meshNode->mNumMeshes = 1;
            meshNode->mMeshes = new unsigned[1]{nextMesh++};
            meshNodes.push_back(meshNode);
        }
        if (!rigged) {
            rootChildren.insert(rootChildren.end(), meshNodes.begin(), meshNodes.end());
            continue;
        }
        const bool gltf = format == ExportFormat::Glb || format == ExportFormat::Gltf;
        rigs.push_back(makeExportRig(*parts[i].part, names[i], parts[i].placement,
                                     options.unitScale,
                                     gltf ? BoneAxes::GltfRootLeavesMinusZ : BoneAxes::PlusY));
        makeBoneNamesUnique(rigs.back(), usedNames);
        for (std::size_t k = 0; k < items.size(); ++k)
            addBones(scene.mMeshes[firstMesh + k], *items[k].part, rigs.back(), influences,
                     options.leafBones);
        std::vector<aiNode*> bones = boneNodes(rigs.back(), options.leafBones);
        if (format == ExportFormat::Fbx)  // the mesh nodes go into their armature
            bones.insert(bones.begin(), meshNodes.begin(), meshNodes.end());
        else
            rootChildren.insert(rootChildren.end(), meshNodes.begin(), meshNodes.end());
        if (format != ExportFormat::Collada) {
            aiNode* armature = new aiNode(uniqueName(names[i] + "_armature", usedNames));
            setChildren(armature, bones);
            rootChildren.push_back(armature);
        } else {
            armatureChildren.insert(armatureChildren.end(), bones.begin(), bones.end());
        }
        if (!options.animation)
            continue;
        std::vector<const Clip*> clips = parts[i].otherClips;
        clips.insert(clips.begin(),
                     parts[i].clip != nullptr ? parts[i].clip : (i == 0 ? clip : nullptr));
        for (const Clip* partClip : clips)
            if (partClip != nullptr && partClip->keyCount() > 0)
                animationGroups.add(partClip->name.empty() ? names[i] + "_clip" : partClip->name,
                                    {partClip, rigs.size() - 1});
    }
    // Made once every rig is in place (`rigs` no longer moves).
    for (const auto& [name, members] : animationGroups.groups) {
        std::vector<AnimatedRig> animated;
        for (const auto& [partClip, rig] : members)
            animated.push_back({partClip, &rigs[rig]});
        animations.push_back(makeAnimation(animated, name));
        // Assimp 5.2.5's FBX exporter writes the stack's LocalStop as the
        // duration cut to whole seconds, and FBX readers drop the keys after
        // it (docs/EXCHANGE.md rule 20): a whole number of seconds keeps them.
        if (format == ExportFormat::Fbx) {
            animations.back()->mDuration = std::ceil(animations.back()->mDuration);
            keepConstantChannelsAsOneKey(*animations.back());
        }
    }
    if (!armatureChildren.empty()) {
        aiNode* armature = new aiNode("Armature");
        setChildren(armature, armatureChildren);
        rootChildren.push_back(armature);
    }
    setChildren(scene.mRootNode, rootChildren);

    scene.mNumMaterials = 1;
    scene.mMaterials = new aiMaterial* [1] { makeMaterial() };

    if (!animations.empty()) {
        scene.mNumAnimations = static_cast<unsigned>(animations.size());
        scene.mAnimations = new aiAnimation*[animations.size()];
        std::copy(animations.begin(), animations.end(), scene.mAnimations);
    }
    if (format == ExportFormat::Fbx) {
        // docs/EXCHANGE.md rule 10: FBX defaults to centimetres; 100 says metres.
        scene.mMetaData = aiMetadata::Alloc(1);
        scene.mMetaData->Set(0, "UnitScaleFactor", 100.0);
    }
    return rigs;
}

}  // namespace rigmesh
