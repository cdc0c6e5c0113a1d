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

void require(bool ok, const std::string& what) {
    if (!ok)
        throw Error("cannot export: " + what + " is not a finite number");
}

void checkMesh(const aiMesh& mesh) {
    const std::string name = "mesh '" + std::string(mesh.mName.C_Str()) + "'";
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        require(finite(mesh.mVertices[v]), "vertex " + std::to_string(v) + " of " + name);
        if (mesh.mNormals != nullptr)
            require(finite(mesh.mNormals[v]),
                    "the normal of vertex " + std::to_string(v) + " of " + name);
    }
    for (unsigned b = 0; b < mesh.mNumBones; ++b) {
        const aiBone& bone = *mesh.mBones[b];
        const std::string boneName = "bone '" + std::string(bone.mName.C_Str()) + "'";
        require(finite(bone.mOffsetMatrix), "the bind matrix of " + boneName);
        for (unsigned w = 0; w < bone.mNumWeights; ++w)
            require(std::isfinite(bone.mWeights[w].mWeight), "a weight of " + boneName);
    }
}

void checkNode(const aiNode& node) {
    require(finite(node.mTransformation),
            "the transform of node '" + std::string(node.mName.C_Str()) + "'");
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        checkNode(*node.mChildren[c]);
}

void checkChannel(const aiNodeAnim& channel) {
    const std::string name = "a key of '" + std::string(channel.mNodeName.C_Str()) + "'";
    for (unsigned k = 0; k < channel.mNumPositionKeys; ++k)
        require(std::isfinite(channel.mPositionKeys[k].mTime) &&
                    finite(channel.mPositionKeys[k].mValue),
                name);
    for (unsigned k = 0; k < channel.mNumRotationKeys; ++k)
        require(std::isfinite(channel.mRotationKeys[k].mTime) &&
                    finite(channel.mRotationKeys[k].mValue),
                name);
    for (unsigned k = 0; k < channel.mNumScalingKeys; ++k)
        require(
            std::isfinite(channel.mScalingKeys[k].mTime) && finite(channel.mScalingKeys[k].mValue),
            name);
}

}  // namespace

void checkSceneIsFinite(const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m)
        checkMesh(*scene.mMeshes[m]);
    if (scene.mRootNode != nullptr)
        checkNode(*scene.mRootNode);
    for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
        const aiAnimation& animation = *scene.mAnimations[a];
        require(std::isfinite(animation.mDuration), "the animation's duration");
        for (unsigned c = 0; c < animation.mNumChannels; ++c)
            checkChannel(*animation.mChannels[c]);
    }
}

}  // namespace rigmesh
