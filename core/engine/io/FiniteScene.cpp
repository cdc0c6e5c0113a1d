#include "io/FiniteScene.h"

#include <assimp/scene.h>

#include <cmath>
#include <string>

#include "base/Error.h"

namespace rigmesh {
namespace {

bool finite(const aiVector3D& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool finite(const aiQuaternion& q) {
    return std::isfinite(q.w) && std::isfinite(q.x) && std::isfinite(q.y) && std::isfinite(q.z);
}

bool finite(const aiMatrix4x4& m) {
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c)
            if (!std::isfinite(m[r][c]))
                return false;
    return true;
}

// Refuses with the message `id` and its arguments unless `ok`.
template <class... Args>
void require(bool ok, MessageId id, const Args&... args) {
    if (!ok)
        throw Error(id, args...);
}

void checkMesh(const aiMesh& mesh) {
    const std::string name = mesh.mName.C_Str();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        require(finite(mesh.mVertices[v]), MessageId::ExportVertexNotFinite, v, name);
        if (mesh.mNormals != nullptr)
            require(finite(mesh.mNormals[v]), MessageId::ExportNormalNotFinite, v, name);
    }
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const aiBone& bone = *mesh.mBones[b];
        const std::string boneName = bone.mName.C_Str();
        require(finite(bone.mOffsetMatrix), MessageId::ExportBindMatrixNotFinite, boneName);
        for (unsigned w = 0; w < bone.mNumWeights; ++w)
            require(std::isfinite(bone.mWeights[w].mWeight), MessageId::ExportBoneWeightNotFinite,
                    boneName);
    }
}

void checkNode(const aiNode& node) {
    require(finite(node.mTransformation), MessageId::ExportNodeTransformNotFinite,
            std::string(node.mName.C_Str()));
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        checkNode(*node.mChildren[c]);
}

void checkChannel(const aiNodeAnim& channel) {
    const std::string name = channel.mNodeName.C_Str();
    for (unsigned k = 0; k < channel.mNumPositionKeys; ++k)
        require(std::isfinite(channel.mPositionKeys[k].mTime) &&
                    finite(channel.mPositionKeys[k].mValue),
                MessageId::ExportKeyNotFinite, name);
    for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
        require(std::isfinite(channel.mRotationKeys[k].mTime) &&
                    finite(channel.mRotationKeys[k].mValue),
                MessageId::ExportKeyNotFinite, name);
    for (unsigned k = 0; k < channel.mNumScalingKeys; ++k)
        require(
            std::isfinite(channel.mScalingKeys[k].mTime) && finite(channel.mScalingKeys[k].mValue),
            MessageId::ExportKeyNotFinite, name);
}

}  // namespace

void checkSceneIsFinite(const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        checkMesh(*scene.mMeshes[m]);
    if (scene.mRootNode != nullptr)
        checkNode(*scene.mRootNode);
    for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
        const aiAnimation& animation = *scene.mAnimations[a];
        require(std::isfinite(animation.mDuration), MessageId::ExportDurationNotFinite);
        for (unsigned c = 0; c < animation.mNumChannels; ++c)
            checkChannel(*animation.mChannels[c]);
    }
}

}  // namespace rigmesh
