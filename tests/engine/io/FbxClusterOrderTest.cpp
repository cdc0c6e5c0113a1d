// Every FBX we write lists a mesh's bones parents first
// (io/FbxClusterOrder.h): a reader that adds bones in the file's cluster
// order and looks each parent up among the bones added so far (Godot 3.2's
// FBX import, docs/EXCHANGE.md rule 15) then keeps every parent.
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <assimp/Importer.hpp>

#include <set>
#include <string>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/FbxClusterOrder.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"

namespace rigmesh {
namespace {

using Param = std::tuple<std::string, bool>;  // sketch, leaf bones

class FbxClusterOrder : public testing::TestWithParam<Param> {};

TEST_P(FbxClusterOrder, EachBoneComesAfterItsParentInTheMeshsBoneList) {
    const auto& [sketch, leafBones] = GetParam();
    const Part& part = iotest::sharedPart(sketch);
    const Clip clip = poseDemoClip(part);
    const std::string path =
        (iotest::scratchFolder() / (sketch + (leafBones ? "_leaves" : "") + "_order.fbx")).string();
    ExportPart item;
    item.part = &part;
    ExportOptions options;
    options.leafBones = leafBones;
    exportScene({item}, &clip, path, options);

    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    ASSERT_GE(scene->mNumMeshes, 1u);
    const aiMesh* mesh = scene->mMeshes[0];
    std::set<std::string> bones;
    for (unsigned b = 0; b < mesh->mNumBones; ++b)
        bones.insert(mesh->mBones[b]->mName.C_Str());
    EXPECT_GE(mesh->mNumBones, static_cast<unsigned>(part.skeleton.boneCount()));
    int parentsOfBones = 0;
    std::set<std::string> added;
    for (unsigned b = 0; b < mesh->mNumBones; ++b) {
        const std::string name = mesh->mBones[b]->mName.C_Str();
        const aiNode* node = scene->mRootNode->FindNode(mesh->mBones[b]->mName);
        ASSERT_NE(node, nullptr) << name;
        if (node->mParent != nullptr && bones.contains(node->mParent->mName.C_Str())) {
            ++parentsOfBones;
            EXPECT_TRUE(added.contains(node->mParent->mName.C_Str()))
                << name << " comes before its parent " << node->mParent->mName.C_Str();
        }
        added.insert(name);
    }
    EXPECT_GT(parentsOfBones, 0) << "the rig has no bone under another bone";
}

// Sketches whose rigs hang bones under bones (y_branch and camel_body hang
// every bone from a root joint that is no bone of the mesh).
INSTANTIATE_TEST_SUITE_P(SharedSketches, FbxClusterOrder,
                         testing::Combine(testing::Values("biped", "star", "banana"),
                                          testing::Bool()),
                         [](const testing::TestParamInfo<Param>& param) {
                             return std::get<0>(param.param) +
                                    (std::get<1>(param.param) ? "_leaf_bones" : "");
                         });

TEST(FbxClusterOrderPass, BytesThatAreNoFbxAreRefused) {
    const std::string text = "Kaydara FBX Binary? no, some text";
    EXPECT_THROW(withFbxClustersParentsFirst(std::vector<std::uint8_t>(text.begin(), text.end())),
                 Error);
}

}  // namespace
}  // namespace rigmesh
