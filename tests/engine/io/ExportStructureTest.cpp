// The aiScene of every rigged export as Assimp reads it back, without any
// post-processing: one node per bone named after it, unique names, parents
// by the bone hierarchy, inverse bind matrices = inverse of the bone's head
// transform, normalised weights (<= 4 for glTF), channels with equal keys.
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>

#include <map>
#include <set>

#include "IoTestSupport.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"

namespace rigmesh {
namespace {

using Param = std::tuple<std::string, std::string>;

void collect(const aiNode* node, std::map<std::string, const aiNode*>& byName, int& count) {
    byName[node->mName.C_Str()] = node;
    ++count;
    for (unsigned c = 0; c < node->mNumChildren; ++c)
        collect(node->mChildren[c], byName, count);
}

aiMatrix4x4 global(const aiNode* node) {
    aiMatrix4x4 m = node->mTransformation;
    for (const aiNode* up = node->mParent; up != nullptr; up = up->mParent)
        m = up->mTransformation * m;
    return m;
}

class Structure : public testing::TestWithParam<Param> {};

TEST_P(Structure, NodesBonesWeightsAndChannels) {
    const auto& [extension, sketch] = GetParam();
    const Part& part = iotest::sharedPart(sketch);
    const Clip clip = poseDemoClip(part);
    const std::string path = (iotest::scratchFolder() / (sketch + extension)).string();
    ExportPart item;
    item.part = &part;
    exportScene({item}, &clip, path);  // default: at most 4 influences

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    std::map<std::string, const aiNode*> byName;
    int count = 0;
    collect(scene->mRootNode, byName, count);
    EXPECT_EQ(static_cast<int>(byName.size()), count) << "node names are not unique";
    // One armature node per part, but for COLLADA: every
    // bone under `Armature`.
    const std::string armature = extension == ".dae" ? "Armature" : sketch + "_armature";
    ASSERT_TRUE(byName.contains(armature));
    ASSERT_GE(scene->mNumMeshes, 1u);
    ASSERT_GE(scene->mNumMaterials, 1u);

    const aiMesh* mesh = scene->mMeshes[0];
    ASSERT_EQ(mesh->mNumBones, static_cast<unsigned>(part.skeleton.boneCount()));
    const double size = iotest::meshSize(part.mesh);
    std::vector<double> sums(mesh->mNumVertices, 0.0);
    std::vector<int> counts(mesh->mNumVertices, 0);
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        const aiBone* bone = mesh->mBones[b];
        const std::string name = bone->mName.C_Str();
        ASSERT_TRUE(byName.contains(name)) << "bone without node: " << name;
        // Our bone of that name: its head, and its parent bone's node.
        int ours = -1;
        for (int i = 0; i < part.skeleton.boneCount(); ++i)
            if (name == sketch + "_bone" +
                            std::to_string(part.skeleton.bones()[static_cast<std::size_t>(i)].id))
                ours = i;
        ASSERT_GE(ours, 0) << name;
        const Bone& our = part.skeleton.bones()[static_cast<std::size_t>(ours)];
        const Vec3 head = part.skeleton.joint(our.head).position;
        // Inverse bind matrix = inverse of the head's (translation) transform.
        aiMatrix4x4 bind = global(byName[name]);
        EXPECT_NEAR(bind.a4, head.x(), 1e-5 * size);
        EXPECT_NEAR(bind.b4, head.y(), 1e-5 * size);
        EXPECT_NEAR(bind.c4, head.z(), 1e-5 * size);
        const aiMatrix4x4 product = bind * bone->mOffsetMatrix;
        for (unsigned r = 0; r < 4; ++r)
            for (unsigned c = 0; c < 4; ++c)
                EXPECT_NEAR(product[r][c], r == c ? 1.0 : 0.0, 1e-5) << name;
        const auto parent = part.skeleton.parentBone(our.id);
        const std::string parentName =
            parent ? sketch + "_bone" + std::to_string(*parent) : armature;
        std::string actualParent = byName[name]->mParent->mName.C_Str();
        EXPECT_EQ(actualParent, parentName) << name;
        for (unsigned w = 0; w < bone->mNumWeights; ++w) {
            sums[bone->mWeights[w].mVertexId] += bone->mWeights[w].mWeight;
            ++counts[bone->mWeights[w].mVertexId];
        }
    }
    for (unsigned v = 0; v < mesh->mNumVertices; ++v) {
        EXPECT_NEAR(sums[v], 1.0, 1e-5) << "vertex " << v;
        EXPECT_LE(counts[v], 4) << "vertex " << v;
    }

    ASSERT_EQ(scene->mNumAnimations, 1u);
    const aiAnimation* animation = scene->mAnimations[0];
    EXPECT_GE(animation->mNumChannels, static_cast<unsigned>(part.skeleton.boneCount()));
    for (unsigned c = 0; c < animation->mNumChannels; ++c) {
        const aiNodeAnim* channel = animation->mChannels[c];
        EXPECT_TRUE(byName.contains(channel->mNodeName.C_Str()));
        EXPECT_EQ(channel->mNumPositionKeys, channel->mNumRotationKeys)
            << channel->mNodeName.C_Str();
        EXPECT_EQ(channel->mNumScalingKeys, channel->mNumRotationKeys)
            << channel->mNodeName.C_Str();
        for (unsigned k = 0; k < std::min(channel->mNumPositionKeys, channel->mNumRotationKeys);
             ++k)
            EXPECT_NEAR(channel->mPositionKeys[k].mTime, channel->mRotationKeys[k].mTime, 1e-6);
    }
}

std::string paramName(const testing::TestParamInfo<Param>& info) {
    return std::get<0>(info.param).substr(1) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Formats, Structure,
                         testing::Combine(testing::Values(".glb", ".gltf", ".fbx", ".dae"),
                                          testing::Values("tube", "y_branch", "biped")),
                         paramName);

}  // namespace
}  // namespace rigmesh
