#include "io/AssimpJoinVertices.h"

#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/version.h>

#include <array>
#include <cstring>
#include <unordered_map>
#include <vector>

namespace rigmesh {
namespace {

using VertexKey = std::array<float, 6>;  // position, normal

struct VertexKeyHash {
    std::size_t operator()(const VertexKey& key) const {
        std::size_t hash = 14695981039346656037ull;
        unsigned char bytes[sizeof(VertexKey)];
        std::memcpy(bytes, key.data(), sizeof bytes);
        for (const unsigned char b : bytes)
            hash = (hash ^ b) * 1099511628211ull;
        return hash;
    }
};

struct VertexKeyEqual {
    bool operator()(const VertexKey& a, const VertexKey& b) const {
        return std::memcmp(a.data(), b.data(), sizeof(VertexKey)) == 0;  // bits, so -0 != 0
    }
};

VertexKey keyOf(const aiMesh& mesh, unsigned v) {
    const aiVector3D& p = mesh.mVertices[v];
    const aiVector3D n = mesh.mNormals != nullptr ? mesh.mNormals[v] : aiVector3D();
    return {p.x, p.y, p.z, n.x, n.y, n.z};
}

// Assimp 5.2's ScenePrivateData (code/Common/ScenePrivate.h), behind
// aiScene::mPrivate: the exporter skips the steps in mPPStepsApplied.
struct AssimpScenePrivateData {
    void* mOrigImporter;
    unsigned int mPPStepsApplied;
    bool mIsCopy;
};

}  // namespace

void joinIdenticalVertices(aiMesh& mesh) {
    // Only what our exporter builds: positions, normals and bones. A mesh
    // with other per-vertex channels is left to Assimp's own (slower) join.
    if (mesh.GetNumUVChannels() > 0 || mesh.GetNumColorChannels() > 0 ||
        mesh.HasTangentsAndBitangents() || mesh.mNumAnimMeshes > 0)
        return;
    const unsigned count = mesh.mNumVertices;
    // Each vertex's (bone, weight) list: duplicates merge only when their
    // skinning is the same too.
    std::vector<std::vector<std::pair<unsigned, float>>> weightsOf(count);
    for (unsigned b = 0; b < mesh.mNumBones; ++b)
        for (unsigned w = 0; w < mesh.mBones[b]->mNumWeights; ++w) {
            const aiVertexWeight& weight = mesh.mBones[b]->mWeights[w];
            if (weight.mVertexId < count)
                weightsOf[weight.mVertexId].emplace_back(b, weight.mWeight);
        }
    std::unordered_map<VertexKey, unsigned, VertexKeyHash, VertexKeyEqual> firstOf;
    firstOf.reserve(count);
    std::vector<unsigned> newIndex(count);
    std::vector<unsigned> originalOf;  // per new index: the vertex it keeps
    originalOf.reserve(count);
    std::vector<bool> kept(count, false);
    unsigned next = 0;
    for (unsigned v = 0; v < count; ++v) {
        const auto [it, inserted] = firstOf.try_emplace(keyOf(mesh, v), next);
        if (inserted || weightsOf[originalOf[it->second]] != weightsOf[v]) {
            kept[v] = true;
            newIndex[v] = next++;
            originalOf.push_back(v);
        } else {
            newIndex[v] = it->second;
        }
    }
    if (next == count)
        return;
    for (unsigned v = 0; v < count; ++v)
        if (kept[v]) {
            mesh.mVertices[newIndex[v]] = mesh.mVertices[v];
            if (mesh.mNormals != nullptr)
                mesh.mNormals[newIndex[v]] = mesh.mNormals[v];
        }
    mesh.mNumVertices = next;  // the arrays keep their size; Assimp reads mNumVertices
    for (unsigned f = 0; f < mesh.mNumFaces; ++f)
        for (unsigned k = 0; k < mesh.mFaces[f].mNumIndices; ++k)
            mesh.mFaces[f].mIndices[k] = newIndex[mesh.mFaces[f].mIndices[k]];
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        aiBone& bone = *mesh.mBones[b];
        unsigned written = 0;
        for (unsigned w = 0; w < bone.mNumWeights; ++w) {
            const aiVertexWeight weight = bone.mWeights[w];
            if (kept[weight.mVertexId])
                bone.mWeights[written++] =
                    aiVertexWeight(newIndex[weight.mVertexId], weight.mWeight);
        }
        bone.mNumWeights = written;
    }
}

bool markVerticesJoined(aiScene& scene) {
    // The layout above is that of Assimp 5.2 (Debian 12 ships 5.2.5); on any
    // other version the exporter runs its own join (slower, still correct).
    if (aiGetVersionMajor() != 5 || aiGetVersionMinor() != 2 || aiGetVersionPatch() > 5 ||
        scene.mPrivate == nullptr)
        return false;
    auto* data = static_cast<AssimpScenePrivateData*>(scene.mPrivate);
    // A scene we built: no importer, not a copy (the exporter ignores copies).
    if (data->mOrigImporter != nullptr || data->mIsCopy)
        return false;
    data->mPPStepsApplied |= aiProcess_JoinIdenticalVertices;
    return true;
}

}  // namespace rigmesh
