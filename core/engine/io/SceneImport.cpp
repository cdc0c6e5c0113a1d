#include "io/SceneImport.h"

#include <tinyxml2.h>

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <set>

#include "base/Error.h"
#include "base/MessageText.h"
#include "io/AssimpBoneHints.h"
#include "io/AssimpConversions.h"
#include "io/AssimpNodeTree.h"
#include "io/AssimpRigImport.h"
#include "io/BoneTipHints.h"
#include "io/ColladaActionNames.h"

namespace rigmesh {
namespace {

// Assimp's reason for refusing a file, when it is a short sentence; a long
// one quotes the file's own data (a whole float array) or the library's
// internals, and says nothing more than "it cannot be read".
constexpr std::size_t kMaxReaderReason = 120;

// Messages name the file, not the folders it is in.
std::string fileName(const std::string& path) {
    return std::filesystem::path(path).filename().string();
}

Error unreadable(const std::string& path, const std::string& reason) {
    const std::string line = oneLine(reason, std::string::npos);
    if (line.empty() || line.size() > kMaxReaderReason)
        return Error(MessageId::ImportUnknownFormat, fileName(path));
    return Error(MessageId::ImportUnreadable, fileName(path), line);
}

const aiScene* readScene(Assimp::Importer& importer, const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw Error(MessageId::ImportNoSuchFile, fileName(path));
    // FBX pivots as extra `$AssimpFbx$` nodes would split bones from their nodes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    // Every FBX animation curve, also one that holds the rest pose: by
    // default Assimp drops such curves, and with them a one-key clip (a
    // Half-Life or SMD reference pose) whole.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_OPTIMIZE_EMPTY_ANIMATION_CURVES, false);
    // COLLADA nodes by their names (Blender's "Lower"), not their ids
    // ("Rig_Lower"): the names a rigger gave the bones.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_USE_COLLADA_NAMES, true);
    const aiScene* scene = nullptr;
    try {
        scene =
            importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                        aiProcess_SortByPType | aiProcess_ValidateDataStructure);
    } catch (const std::exception& exception) {
        throw unreadable(path, exception.what());
    }
    if (scene == nullptr)
        throw unreadable(path, importer.GetErrorString());
    if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr)
        throw Error(MessageId::ImportIncomplete, fileName(path));
    return scene;
}

bool isCollada(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return extension == ".dae";
}

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// FBX says its unit in centimetres per file unit (UnitScaleFactor; 100 =
// metres, as we write; Blender writes 1 with a 100x armature and mesh), and
// Assimp 5.2.5 leaves it to us; Blender's importer applies it. glTF is in
// metres, and Assimp applies COLLADA's <unit> itself.
double metresPerFileUnit(const aiScene& scene) {
    if (scene.mMetaData == nullptr)
        return 1.0;
    for (unsigned i = 0; i < scene.mMetaData->mNumProperties; ++i) {
        if (std::string(scene.mMetaData->mKeys[i].C_Str()) != "UnitScaleFactor")
            continue;
        const aiMetadataEntry& entry = scene.mMetaData->mValues[i];
        double centimetres = 0;
        if (entry.mType == AI_DOUBLE && entry.mData != nullptr)
            centimetres = *static_cast<const double*>(entry.mData);
        else if (entry.mType == AI_FLOAT && entry.mData != nullptr)
            centimetres = *static_cast<const float*>(entry.mData);
        if (std::isfinite(centimetres) && centimetres > 0)
            return centimetres / 100.0;
    }
    return 1.0;
}

// The file's bone names on the part's bones, when they are distinct and
// not empty (as Part::validate wants them).
void keepBoneNames(ImportedPart& imported) {
    const std::set<std::string> distinct(imported.boneNames.begin(), imported.boneNames.end());
    if (distinct.size() != imported.boneNames.size() || distinct.contains(""))
        return;
    for (std::size_t b = 0; b < imported.boneNames.size(); ++b)
        imported.part.boneNames[imported.part.skeleton.bones()[b].id] = imported.boneNames[b];
}

// Where a mesh's vertices are shown: for a skinned mesh whose bones' nodes
// rest in its bind pose, a bone node's global transform times its offset
// matrix (glTF ignores a skinned mesh node's own transform; COLLADA's
// bind_shape_matrix, which Assimp folds into the offsets, moves the mesh,
// and Blender shows it there); else the mesh node's global transform.
Eigen::Affine3d meshToWorld(const aiMesh& mesh, const Eigen::Affine3d& nodeGlobal,
                            const AssimpNodeTree& tree) {
    std::optional<Eigen::Affine3d> skin;
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const int node = tree.find(mesh.mBones[b]->mName.C_Str());
        if (node < 0)
            return nodeGlobal;
        const Eigen::Affine3d candidate =
            tree.restGlobal(node) * fromAi(mesh.mBones[b]->mOffsetMatrix);
        if (!candidate.matrix().allFinite())
            return nodeGlobal;
        if (!skin)
            skin = candidate;
        else if (!skin->matrix().isApprox(candidate.matrix(), 1e-5))
            return nodeGlobal;  // the nodes rest in another pose than the bind pose
    }
    return skin ? *skin : nodeGlobal;
}

// Blender's FBX exporter names a take `<armature>|<action>`: the action.
std::string actionName(const std::string& animation) {
    const auto bar = animation.rfind('|');
    return bar == std::string::npos ? animation : animation.substr(bar + 1);
}

struct MeshInstance {
    unsigned mesh;
    int node;
};

}  // namespace

ImportedScene importScene(const std::string& path) {
    Assimp::Importer importer;
    const aiScene& scene = *readScene(importer, path);
    const AssimpNodeTree tree(scene, metresPerFileUnit(scene));

    std::vector<MeshInstance> instances;
    std::set<unsigned> seen;
    for (int n = 0; n < tree.size(); ++n)
        for (unsigned k = 0; k < tree.node(n).mNumMeshes; ++k) {
            const unsigned m = tree.node(n).mMeshes[k];
            if (m < scene.mNumMeshes && seen.insert(m).second &&
                (scene.mMeshes[m]->mPrimitiveTypes & aiPrimitiveType_TRIANGLE) != 0)
                instances.push_back({m, n});
        }
    if (instances.empty())
        throw Error(MessageId::ImportNoTriangleMesh, fileName(path));

    std::set<std::string> weightedAnywhere;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        for (unsigned b = 0; b < scene.mMeshes[m]->mNumBones; ++b)
            for (unsigned w = 0; w < scene.mMeshes[m]->mBones[b]->mNumWeights; ++w)
                if (scene.mMeshes[m]->mBones[b]->mWeights[w].mWeight > 0) {
                    weightedAnywhere.insert(scene.mMeshes[m]->mBones[b]->mName.C_Str());
                    break;
                }

    RigHints hints;
    std::map<std::string, std::string> colladaActions;
    for (unsigned a = 0; a < scene.mNumAnimations; ++a)
        for (unsigned c = 0; c < scene.mAnimations[a]->mNumChannels; ++c)
            hints.animatedNodes.insert(scene.mAnimations[a]->mChannels[c]->mNodeName.C_Str());
    if (isCollada(path)) {
        // One parse for all of Blender's and our extras (Assimp has its own).
        const std::string text = readText(path);
        tinyxml2::XMLDocument dae;
        if (dae.Parse(text.data(), text.size()) == tinyxml2::XML_SUCCESS &&
            dae.RootElement() != nullptr) {
            const tinyxml2::XMLElement& collada = *dae.RootElement();
            hints.colladaTips = readColladaBoneTips(collada);
            hints.colladaExactTips = readColladaBoneTips(collada, "rigmesh");
            hints.colladaConnections = readColladaBoneConnections(collada);
            hints.colladaNames = readColladaBoneNames(collada);
            colladaActions = readColladaActionNames(collada);
        }
    }

    // Skinned meshes by the skeleton they share, each other mesh alone, in
    // the order of each part's first mesh.
    std::vector<SkinnedMesh> skinned;
    std::vector<std::vector<SkinnedMesh>> parts;
    for (const MeshInstance& instance : instances) {
        const aiMesh& mesh = *scene.mMeshes[instance.mesh];
        const SkinnedMesh item{instance.mesh, instance.node,
                               meshToWorld(mesh, tree.restGlobal(instance.node), tree)};
        if (mesh.mNumBones > 0)
            skinned.push_back(item);
        else
            parts.push_back({item});
    }
    std::vector<std::vector<SkinnedMesh>> groups =
        groupBySkeleton(scene, tree, skinned, weightedAnywhere, hints);
    parts.insert(parts.end(), groups.begin(), groups.end());
    std::stable_sort(parts.begin(), parts.end(), [](const auto& a, const auto& b) {
        return a.front().node < b.front().node ||
               (a.front().node == b.front().node && a.front().mesh < b.front().mesh);
    });

    ImportedScene result;
    for (const std::vector<SkinnedMesh>& group : parts) {
        const aiMesh& first = *scene.mMeshes[group.front().mesh];
        ImportedPart imported;
        imported.part.name = meshName(first, tree.node(group.front().node));
        ImportedBones bones;
        std::string why = "it has no skeleton";
        if (first.mNumBones > 0)
            why = importRig(scene, group, tree, weightedAnywhere, hints, imported, bones);
        else
            imported.part.mesh = worldMesh(first, group.front().global);
        imported.part.surfaceFromFile = true;  // as the file has it: maybe open
        if (why.empty()) {
            keepBoneNames(imported);
            for (unsigned a = 0; a < scene.mNumAnimations; ++a)
                if (std::optional<Clip> clip =
                        importClip(*scene.mAnimations[a], tree, imported, bones)) {
                    const std::string animation = scene.mAnimations[a]->mName.C_Str();
                    const auto action = colladaActions.find(animation);
                    clip->name =
                        action != colladaActions.end() ? action->second : actionName(animation);
                    imported.clips.push_back(std::move(*clip));
                }
        } else {
            imported.needsRig = true;
            imported.part.skeleton = Skeleton();
            imported.part.weights = SkinWeightsById();
            imported.part.boneFrames.clear();
            imported.boneNames.clear();
            result.needsRig = true;
            result.message += (result.message.empty() ? "" : "; ") + std::string("part '") +
                              imported.part.name + "' needs a rig before it can be posed (" + why +
                              "); rig it with Tools > Auto-Rig Part or `rigmesh rig`";
        }
        result.parts.push_back(std::move(imported));
    }
    return result;
}

}  // namespace rigmesh
