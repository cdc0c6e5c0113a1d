// Bone frames in every rigged export: each bone node's
// rest frame runs along its bone (+Y; -Z for a glTF leaf bone without a
// parent bone, ExportRig.h), the skinned mesh is a glTF scene root with no
// helper `RootNode`, and every bone's tail survives our own round trip:
// through the leaf tail hints (BoneTipHints.h) by default, through end bones
// with leafBones, which point back along their leaves.
#include <assimp/scene.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <assimp/Importer.hpp>
#include <fstream>
#include <iterator>
#include <map>

#include "IoTestSupport.h"
#include "io/BoneTipHints.h"
#include "io/GltfBuffers.h"
#include "io/GltfSceneRoots.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

using Param = std::tuple<std::string, std::string>;

std::string readAll(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Eigen::Affine3d globalOf(const aiNode* node) {
    aiMatrix4x4 m = node->mTransformation;
    for (const aiNode* up = node->mParent; up != nullptr; up = up->mParent)
        m = up->mTransformation * m;
    Eigen::Matrix4d out;
    for (unsigned r = 0; r < 4; ++r)
        for (unsigned c = 0; c < 4; ++c)
            out(r, c) = m[r][c];
    return Eigen::Affine3d(out);
}

std::string exportTo(const std::string& sketch, const std::string& extension, bool leafBones) {
    const Part& part = iotest::sharedPart(sketch);
    const std::string path = (iotest::scratchFolder() / (sketch + extension)).string();
    ExportPart item;
    item.part = &part;
    ExportOptions options;
    options.leafBones = leafBones;
    exportScene({item}, nullptr, path, options);
    return path;
}

class BoneFrames : public testing::TestWithParam<Param> {};

TEST_P(BoneFrames, EachBoneNodesAxisRunsFromHeadToTail) {
    const auto& [extension, sketch] = GetParam();
    const Part& part = iotest::sharedPart(sketch);
    const std::string path = exportTo(sketch, extension, false);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(path, 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const bool gltf = extension == ".glb" || extension == ".gltf";
    for (const Bone& bone : part.skeleton.bones()) {
        const std::string name = sketch + "_bone" + std::to_string(bone.id);
        const aiNode* node = scene->mRootNode->FindNode(name.c_str());
        ASSERT_NE(node, nullptr) << name;
        const Vec3 along =
            (part.skeleton.joint(bone.tail).position - part.skeleton.joint(bone.head).position)
                .normalized();
        const bool rootLeaf =
            !part.skeleton.parentBone(bone.id) && part.skeleton.childrenOf(bone.tail).empty();
        const Vec3 axis = gltf && rootLeaf ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitY());
        const Vec3 got = (globalOf(node).linear() * axis).normalized();
        EXPECT_LT(std::acos(std::clamp(got.dot(along), -1.0, 1.0)), 1e-5) << name;
    }
}

TEST_P(BoneFrames, LeafBonesAreEndBonesThatImportBackAsTails) {
    const auto& [extension, sketch] = GetParam();
    const Part& part = iotest::sharedPart(sketch);
    const ImportedScene back = importScene(exportTo(sketch, extension, true));
    ASSERT_EQ(back.parts.size(), 1u);
    ASSERT_FALSE(back.parts[0].needsRig) << back.message;
    const Skeleton& theirs = back.parts[0].part.skeleton;
    ASSERT_EQ(theirs.boneCount(), part.skeleton.boneCount()) << "end bones came back as bones";
    const double size = iotest::meshSize(part.mesh);
    for (int i = 0; i < theirs.boneCount(); ++i) {
        const std::string& name = back.parts[0].boneNames[static_cast<std::size_t>(i)];
        const Bone* ours = nullptr;
        for (const Bone& bone : part.skeleton.bones())
            if (name == sketch + "_bone" + std::to_string(bone.id))
                ours = &bone;
        ASSERT_NE(ours, nullptr) << name;
        const Bone& their = theirs.bones()[static_cast<std::size_t>(i)];
        EXPECT_LE(
            (theirs.joint(their.tail).position - part.skeleton.joint(ours->tail).position).norm(),
            1e-4 * size)
            << name;
    }
}

// Blender gives an end bone its leaf's length along the end node's own bone
// axis (ExportRig.h endBoneOf): the end node sits on the leaf's tail and its
// axis (the leaf's: +Y, or -Z for a glTF root leaf) runs back to the leaf's
// head, so the end bone lies inside the limb.
TEST_P(BoneFrames, EndBonesSitOnTheLeafTailAndPointBackAlongTheLeaf) {
    const auto& [extension, sketch] = GetParam();
    const Part& part = iotest::sharedPart(sketch);
    Assimp::Importer importer;
    const aiScene* scene = importer.ReadFile(exportTo(sketch, extension, true), 0);
    ASSERT_NE(scene, nullptr) << importer.GetErrorString();
    const bool gltf = extension == ".glb" || extension == ".gltf";
    const double size = iotest::meshSize(part.mesh);
    int ends = 0;
    for (const Bone& bone : part.skeleton.bones()) {
        if (!part.skeleton.childrenOf(bone.tail).empty())
            continue;
        const std::string name = sketch + "_bone" + std::to_string(bone.id) + "_end";
        const aiNode* node = scene->mRootNode->FindNode(name.c_str());
        ASSERT_NE(node, nullptr) << name;
        ++ends;
        const Vec3 head = part.skeleton.joint(bone.head).position;
        const Vec3 tail = part.skeleton.joint(bone.tail).position;
        const Eigen::Affine3d global = globalOf(node);
        EXPECT_LE((global.translation() - tail).norm(), 1e-5 * size) << name;
        const bool rootLeaf = !part.skeleton.parentBone(bone.id);
        const Vec3 axis = gltf && rootLeaf ? Vec3(-Vec3::UnitZ()) : Vec3(Vec3::UnitY());
        const Vec3 got = (global.linear() * axis).normalized();
        EXPECT_LT(std::acos(std::clamp(got.dot((head - tail).normalized()), -1.0, 1.0)), 1e-5)
            << name;
    }
    EXPECT_GT(ends, 0);
}

std::string paramName(const testing::TestParamInfo<Param>& info) {
    return std::get<0>(info.param).substr(1) + "_" + std::get<1>(info.param);
}

INSTANTIATE_TEST_SUITE_P(Formats, BoneFrames,
                         testing::Combine(testing::Values(".glb", ".gltf", ".fbx", ".dae"),
                                          testing::Values("tube", "y_branch", "biped")),
                         paramName);

// Blender's glTF importer points a bone at its children snapped to the
// nearest axis of its node's frame (docs/EXCHANGE.md rules 22 and 27): a
// leaf of an imported rig, whose frame is kept from its file, goes out with
// one axis of its frame along the bone towards its end bone, so that Blender
// lays it along the limb. Testwuson.X's leaves Ear_L/R and ForeLeg_L/R_05
// have no axis within 7 degrees of their bone in the file.
TEST(KeptFramesInGltf, EveryLeafHasAFrameAxisAlongItsBone) {
    for (const std::string model : {"X/Testwuson.X", "X/BCN_Epileptic.X", "SMD/WusonSMD.smd"}) {
        const ImportedScene imported = importScene("/usr/share/assimp/models/" + model);
        std::vector<ExportPart> items;
        for (const ImportedPart& part : imported.parts)
            if (!part.needsRig) {
                ExportPart item;
                item.part = &part.part;
                items.push_back(item);
            }
        ASSERT_FALSE(items.empty()) << model << ": " << imported.message;
        const std::string path = (iotest::scratchFolder() / "kept_frames.glb").string();
        ExportOptions options;
        options.leafBones = true;
        exportScene(items, nullptr, path, options);
        Assimp::Importer importer;
        const aiScene* scene = importer.ReadFile(path, 0);
        ASSERT_NE(scene, nullptr) << importer.GetErrorString();
        int leaves = 0;
        std::vector<const aiNode*> nodes{scene->mRootNode};
        while (!nodes.empty()) {
            const aiNode* node = nodes.back();
            nodes.pop_back();
            for (unsigned c = 0; c < node->mNumChildren; ++c)
                nodes.push_back(node->mChildren[c]);
            const std::string name = node->mName.C_Str();
            if (name.size() < 4 || name.substr(name.size() - 4) != "_end")
                continue;
            ++leaves;
            const Eigen::Affine3d leaf = globalOf(node->mParent);
            const Vec3 along = (globalOf(node).translation() - leaf.translation()).normalized();
            double nearest = M_PI;  // the angle of the frame's axis nearest the bone
            for (int axis = 0; axis < 3; ++axis) {
                const double cosine = std::abs(leaf.linear().col(axis).normalized().dot(along));
                nearest = std::min(nearest, std::acos(std::min(1.0, cosine)));
            }
            // A degree, within which a kept frame stays as read (ExportRig.cpp),
            // and single precision.
            EXPECT_LT(nearest, M_PI / 180.0 + 1e-4)
                << model << ": " << node->mParent->mName.C_Str();
        }
        EXPECT_GT(leaves, 0) << model;
    }
}

TEST(GltfScene, SkinnedMeshIsASceneRootAndNoRootNodeIsWritten) {
    const std::string glb = readAll(exportTo("biped", ".glb", false));
    const nlohmann::json gltf = nlohmann::json::parse(glbJson(glb));
    ASSERT_EQ(gltf["scenes"].size(), 1u);
    bool skinnedRoot = false;
    for (const auto& index : gltf["scenes"][0]["nodes"])
        skinnedRoot = skinnedRoot || gltf["nodes"][index.get<std::size_t>()].contains("skin");
    EXPECT_TRUE(skinnedRoot);
    for (const auto& node : gltf["nodes"])
        EXPECT_NE(node.value("name", ""), "RootNode");
}

TEST(GltfScene, EachPartHasItsOwnSkinOfItsOwnBones) {
    const Part& tube = iotest::sharedPart("tube");
    const Part& biped = iotest::sharedPart("biped");
    ExportPart a, b;
    a.part = &tube;
    b.part = &biped;
    const std::string path = (iotest::scratchFolder() / "two.glb").string();
    exportScene({a, b}, nullptr, path);
    const nlohmann::json gltf = nlohmann::json::parse(glbJson(readAll(path)));
    ASSERT_EQ(gltf["skins"].size(), 2u);
    std::map<std::string, int> bonesOfPart = {{"tube", tube.skeleton.boneCount()},
                                              {"biped", biped.skeleton.boneCount()}};
    for (const auto& node : gltf["nodes"]) {
        if (!node.contains("skin"))
            continue;
        const std::string part = node["name"];
        const auto& skin = gltf["skins"][node["skin"].get<std::size_t>()];
        EXPECT_EQ(skin["name"], part + "_armature");
        ASSERT_EQ(static_cast<int>(skin["joints"].size()), bonesOfPart.at(part));
        for (const auto& joint : skin["joints"])
            EXPECT_EQ(gltf["nodes"][joint.get<std::size_t>()]["name"].get<std::string>().rfind(
                          part + "_bone", 0),
                      0u);
    }
    // And back: each part with its own bones and weights.
    const ImportedScene back = importScene(path);
    ASSERT_EQ(back.parts.size(), 2u);
    EXPECT_FALSE(back.needsRig) << back.message;
    EXPECT_EQ(back.parts[0].part.skeleton.boneCount() + back.parts[1].part.skeleton.boneCount(),
              tube.skeleton.boneCount() + biped.skeleton.boneCount());
}

TEST(GltfScene, LiftingTheRootRenumbersEveryNodeReference) {
    const nlohmann::json before = {{"scenes", {{{"nodes", {0}}}}},
                                   {"nodes",
                                    {{{"name", "root"}, {"children", {1, 2}}},
                                     {{"name", "mesh"}, {"mesh", 0}, {"skin", 0}},
                                     {{"name", "arm"}, {"children", {3}}},
                                     {{"name", "bone"}}}},
                                   {"skins", {{{"joints", {3}}}}},
                                   {"animations", {{{"channels", {{{"target", {{"node", 3}}}}}}}}}};
    const nlohmann::json after = nlohmann::json::parse(withRootChildrenAsSceneRoots(before.dump()));
    EXPECT_EQ(after["scenes"][0]["nodes"], nlohmann::json({0, 1}));
    EXPECT_EQ(after["nodes"].size(), 3u);
    EXPECT_EQ(after["nodes"][1]["children"], nlohmann::json({2}));
    EXPECT_EQ(after["skins"][0]["joints"], nlohmann::json({2}));
    EXPECT_EQ(after["animations"][0]["channels"][0]["target"]["node"], 2);

    nlohmann::json moved = before;  // a root with a transform stays
    moved["nodes"][0]["translation"] = {1, 0, 0};
    EXPECT_EQ(nlohmann::json::parse(withRootChildrenAsSceneRoots(moved.dump())), moved);
}

TEST(ColladaTips, EveryJointCarriesBlendersTipOfItsBone) {
    const Part& part = iotest::sharedPart("biped");
    const std::map<std::string, Vec3> tips =
        readColladaBoneTips(readAll(exportTo("biped", ".dae", false)));
    ASSERT_EQ(static_cast<int>(tips.size()), part.skeleton.boneCount());
    for (const Bone& bone : part.skeleton.bones()) {
        const auto tip = tips.find("biped_bone" + std::to_string(bone.id));
        ASSERT_NE(tip, tips.end());
        const Vec3 ours =
            part.skeleton.joint(bone.tail).position - part.skeleton.joint(bone.head).position;
        EXPECT_LE((tip->second - ours).norm(), 1e-6 * ours.norm());
    }
}

}  // namespace
}  // namespace rigmesh
