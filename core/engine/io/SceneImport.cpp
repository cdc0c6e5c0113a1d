#include "io/SceneImport.h"

#include <assimp/config.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

#include "base/Error.h"
#include "io/AssimpConversions.h"
#include "io/AssimpNodeTree.h"
#include "io/AssimpRigImport.h"
#include "io/BoneTipHints.h"

namespace rigmesh {
namespace {

const aiScene* readScene(Assimp::Importer& importer, const std::string& path) {
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error))
        throw Error("cannot import " + path + ": no such file");
    // FBX pivots as extra `$AssimpFbx$` nodes would split bones from their nodes.
    importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, false);
    const aiScene* scene = nullptr;
    try {
        scene =
            importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                        aiProcess_SortByPType | aiProcess_ValidateDataStructure);
    } catch (const std::exception& exception) {
        throw Error("cannot import " + path + ": " + exception.what());
    }
    if (scene == nullptr)
        throw Error("cannot import " + path + ": " + importer.GetErrorString());
    if ((scene->mFlags & AI_SCENE_FLAGS_INCOMPLETE) != 0 || scene->mRootNode == nullptr)
        throw Error("cannot import " + path + ": the file is incomplete");
    return scene;
}

// Triangles only (points and lines are left out), vertices in world space.
TriMesh worldMesh(const aiMesh& mesh, const Eigen::Affine3d& global) {
    TriMesh out;
    out.vertices.reserve(mesh.mNumVertices);
    for (unsigned v = 0; v < mesh.mNumVertices; ++v)
        out.vertices.push_back(global * fromAi(mesh.mVertices[v]));
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices == 3)
            out.faces.push_back({static_cast<int>(face.mIndices[0]),
                                 static_cast<int>(face.mIndices[1]),
                                 static_cast<int>(face.mIndices[2])});
    }
    return out;
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

struct MeshInstance {
    unsigned mesh;
    int node;
};

}  // namespace

ImportedScene importScene(const std::string& path) {
    Assimp::Importer importer;
    const aiScene& scene = *readScene(importer, path);
    const AssimpNodeTree tree(scene);

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
        throw Error("cannot import " + path + ": it holds no triangle mesh");

    std::set<std::string> weightedAnywhere;
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        for (unsigned b = 0; b < scene.mMeshes[m]->mNumBones; ++b)
            for (unsigned w = 0; w < scene.mMeshes[m]->mBones[b]->mNumWeights; ++w)
                if (scene.mMeshes[m]->mBones[b]->mWeights[w].mWeight > 0) {
                    weightedAnywhere.insert(scene.mMeshes[m]->mBones[b]->mName.C_Str());
                    break;
                }

    const std::map<std::string, Vec3> colladaTips =
        isCollada(path) ? readColladaBoneTips(readText(path)) : std::map<std::string, Vec3>();

    ImportedScene result;
    for (const MeshInstance& instance : instances) {
        const aiMesh& mesh = *scene.mMeshes[instance.mesh];
        const Eigen::Affine3d& global = tree.restGlobal(instance.node);
        ImportedPart imported;
        imported.part.name =
            mesh.mName.length > 0 ? mesh.mName.C_Str() : tree.node(instance.node).mName.C_Str();
        imported.part.mesh = worldMesh(mesh, global);
        std::string why = "it has no skeleton";
        if (mesh.mNumBones > 0)
            why = importRig(mesh, global, tree, weightedAnywhere, colladaTips, imported);
        if (!why.empty()) {
            imported.needsRig = true;
            imported.part.skeleton = Skeleton();
            imported.part.weights = SkinWeights();
            imported.boneNames.clear();
            result.needsRig = true;
            result.message += (result.message.empty() ? "" : "; ") + std::string("part '") +
                              imported.part.name + "' needs a rig before it can be posed (" + why +
                              "); rigging imported meshes comes in a later version";
        }
        result.parts.push_back(std::move(imported));
        if (!result.clip && scene.mNumAnimations > 0 && !result.parts.back().needsRig) {
            result.clip =
                importClip(*scene.mAnimations[0], mesh, global, tree, result.parts.back());
            if (result.clip)
                result.clipPart = static_cast<int>(result.parts.size()) - 1;
        }
    }
    return result;
}

}  // namespace rigmesh
