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
    const unsigned count = mesh.mNumVertices;
    std::unordered_map<VertexKey, unsigned, VertexKeyHash, VertexKeyEqual> firstOf;
    firstOf.reserve(count);
    std::vector<unsigned> newIndex(count);
    std::vector<bool> kept(count, false);
    unsigned next = 0;
    for (unsigned v = 0; v < count; ++v) {
        const auto [it, inserted] = firstOf.try_emplace(keyOf(mesh, v), next);
        if (inserted) {
            kept[v] = true;
            ++next;
        }
        newIndex[v] = it->second;
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
    if (aiGetVersionMajor() != 5 || aiGetVersionMinor() != 2 || scene.mPrivate == nullptr)
        return false;
    auto* data = static_cast<AssimpScenePrivateData*>(scene.mPrivate);
    // A scene we built: no importer, not a copy (the exporter ignores copies).
    if (data->mOrigImporter != nullptr || data->mIsCopy)
        return false;
    data->mPPStepsApplied |= aiProcess_JoinIdenticalVertices;
    return true;
}

}  // namespace rigmesh
