// Our linear replacement for Assimp's quadratic JoinIdenticalVertices.
#include <gtest/gtest.h>

#include <assimp/scene.h>

#include "io/AssimpJoinVertices.h"

namespace rigmesh {
namespace {

// Two triangles sharing an edge whose second copy of vertices 1 and 2 is
// split (vertices 3 and 4, weighted as the originals), each vertex weighted
// by one bone.
aiMesh* splitQuad() {
    auto* mesh = new aiMesh;
    const aiVector3D points[] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    mesh->mNumVertices = 6;
    mesh->mVertices = new aiVector3D[6];
    mesh->mNormals = new aiVector3D[6];
    for (unsigned v = 0; v < 6; ++v) {
        mesh->mVertices[v] = points[v];
        mesh->mNormals[v] = aiVector3D(0, 0, 1);
    }
    mesh->mNumFaces = 2;
    mesh->mFaces = new aiFace[2];
    const unsigned corners[2][3] = {{0, 1, 2}, {3, 5, 4}};
    for (unsigned f = 0; f < 2; ++f) {
        mesh->mFaces[f].mNumIndices = 3;
        mesh->mFaces[f].mIndices = new unsigned[3]{corners[f][0], corners[f][1], corners[f][2]};
    }
    mesh->mNumBones = 1;
    mesh->mBones = new aiBone* [1] { new aiBone };
    mesh->mBones[0]->mNumWeights = 6;
    mesh->mBones[0]->mWeights = new aiVertexWeight[6];
    const unsigned original[] = {0, 1, 2, 1, 2, 5};
    for (unsigned v = 0; v < 6; ++v)
        mesh->mBones[0]->mWeights[v] =
            aiVertexWeight(v, 0.1f * static_cast<float>(original[v] + 1));
    return mesh;
}

TEST(AssimpJoinVertices, SplitCopiesMergeIntoTheFirstAndKeepItsWeights) {
    aiScene scene;  // owns the mesh
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh* [1] { splitQuad() };
    aiMesh& mesh = *scene.mMeshes[0];
    joinIdenticalVertices(mesh);
    ASSERT_EQ(mesh.mNumVertices, 4u);
    EXPECT_EQ(mesh.mVertices[3], aiVector3D(1, 1, 0));
    EXPECT_EQ(mesh.mFaces[1].mIndices[0], 1u);
    EXPECT_EQ(mesh.mFaces[1].mIndices[1], 3u);
    EXPECT_EQ(mesh.mFaces[1].mIndices[2], 2u);
    const aiBone& bone = *mesh.mBones[0];
    ASSERT_EQ(bone.mNumWeights, 4u);
    EXPECT_EQ(bone.mWeights[3].mVertexId, 3u);
    EXPECT_FLOAT_EQ(bone.mWeights[3].mWeight, 0.6f);
    EXPECT_FLOAT_EQ(bone.mWeights[1].mWeight, 0.2f);  // the first copy's
}

TEST(AssimpJoinVertices, DifferentNormalsStaySplit) {
    aiScene scene;
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh* [1] { splitQuad() };
    scene.mMeshes[0]->mNormals[3] = aiVector3D(0, 1, 0);
    joinIdenticalVertices(*scene.mMeshes[0]);
    EXPECT_EQ(scene.mMeshes[0]->mNumVertices, 5u);
}

TEST(AssimpJoinVertices, DifferentWeightsStaySplit) {
    aiScene scene;
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh* [1] { splitQuad() };
    scene.mMeshes[0]->mBones[0]->mWeights[3].mWeight = 0.9f;  // copy of vertex 1, other skinning
    joinIdenticalVertices(*scene.mMeshes[0]);
    EXPECT_EQ(scene.mMeshes[0]->mNumVertices, 5u);
}

TEST(AssimpJoinVertices, MeshesWithTextureCoordinatesAreLeftToAssimp) {
    aiScene scene;
    scene.mNumMeshes = 1;
    scene.mMeshes = new aiMesh* [1] { splitQuad() };
    aiMesh& mesh = *scene.mMeshes[0];
    mesh.mTextureCoords[0] = new aiVector3D[6];
    mesh.mNumUVComponents[0] = 2;
    joinIdenticalVertices(mesh);
    EXPECT_EQ(mesh.mNumVertices, 6u);
}

TEST(AssimpJoinVertices, TheLinkedAssimpSkipsItsOwnJoinOnOurScenes) {
    aiScene scene;
    EXPECT_TRUE(markVerticesJoined(scene));
}

}  // namespace
}  // namespace rigmesh
