// A rig made in Blender (tests/data/blender_rig) imported here keeps its bone
// names, its size (FBX unit scale, glTF metres, COLLADA unit) and its action,
// and survives our own export and import in the same format.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "IoTestSupport.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

std::string capsule(const std::string& extension) {
    return std::string(RIGMESH_TEST_DATA) + "/blender_rig/capsule" + extension;
}

// Blender's Z-up (0, 0, z) is our (0, z, 0).
const std::map<std::string, std::pair<double, double>> kBones = {
    {"Lower", {0.0, 1.0}}, {"Middle", {1.0, 2.0}}, {"Upper", {2.0, 3.0}}};

void expectCapsuleRig(const ImportedScene& scene, const std::string& what) {
    ASSERT_EQ(scene.parts.size(), 1u) << what;
    const ImportedPart& imported = scene.parts[0];
    ASSERT_FALSE(imported.needsRig) << what << ": " << scene.message;
    const Part& part = imported.part;
    EXPECT_EQ(part.name, "Capsule") << what;
    EXPECT_TRUE(part.validate().empty()) << what;
    ASSERT_EQ(part.skeleton.boneCount(), 3) << what;
    ASSERT_EQ(part.boneNames.size(), 3u) << what;
    for (const Bone& bone : part.skeleton.bones()) {
        const std::string& name = part.boneNames.at(bone.id);
        ASSERT_TRUE(kBones.contains(name)) << what << ": bone " << name;
        const auto [from, to] = kBones.at(name);
        EXPECT_LE((part.skeleton.joint(bone.head).position - Vec3(0, from, 0)).norm(), 1e-3)
            << what << ": " << name << " head";
        EXPECT_LE((part.skeleton.joint(bone.tail).position - Vec3(0, to, 0)).norm(), 1e-3)
            << what << ": " << name << " tail";
    }
    double top = -1e300, bottom = 1e300;
    for (const Vec3& v : part.mesh.vertices) {
        top = std::max(top, v.y());
        bottom = std::min(bottom, v.y());
    }
    EXPECT_NEAR(top - bottom, 3.0, 1e-3) << what << ": the capsule's height";
    EXPECT_NEAR(bottom, 0.0, 1e-3) << what << ": the capsule stands on the origin";

    ASSERT_FALSE(scene.parts[0].clips.empty()) << what;
    EXPECT_NEAR(scene.parts[0].clips.front().duration(), 23.0 / 24.0, 1e-3) << what;
    // Middle bends 40 degrees half way (frame 12 of 1..24): its rotation is
    // keyed by the joint it ends at (pose/Pose.h).
    JointId middleTail = kNoJoint;
    for (const Bone& bone : part.skeleton.bones())
        if (part.boneNames.at(bone.id) == "Middle")
            middleTail = bone.tail;
    // Blender's glTF and COLLADA exporters put frame 1 at 1/24 s, its FBX
    // exporter at 0 s: the file's times are kept.
    const Pose bent = scene.parts[0].clips.front().evaluate(
        scene.parts[0].clips.front().keyTimes().front() + 11.0 / 24.0);
    const double angle = 2 * std::acos(std::min(1.0, std::abs(bent.rotation(middleTail).w())));
    EXPECT_NEAR(angle * 180 / M_PI, 40.0, 0.5) << what;
}

class BlenderRig : public testing::TestWithParam<std::string> {};

TEST_P(BlenderRig, KeepsBoneNamesSizeAndAction) {
    const ImportedScene scene = importScene(capsule(GetParam()));
    expectCapsuleRig(scene, GetParam());
    if (GetParam() != ".dae") {  // Blender's COLLADA exporter names animations after objects
        EXPECT_EQ(scene.parts[0].clips.front().name, "Wave");
    }
}

TEST_P(BlenderRig, SurvivesOurExportAndImportInTheSameFormat) {
    const ImportedScene scene = importScene(capsule(GetParam()));
    ASSERT_EQ(scene.parts.size(), 1u);
    const std::string path = (iotest::scratchFolder() / ("capsule" + GetParam())).string();
    ExportPart item;
    item.part = &scene.parts[0].part;
    item.clip = scene.parts[0].clips.empty() ? nullptr : &scene.parts[0].clips.front();
    exportScene({item}, nullptr, path);
    const ImportedScene back = importScene(path);
    expectCapsuleRig(back, GetParam() + " exported again");
    // Assimp's COLLADA writer and reader do not keep an animation's name.
    if (!scene.parts[0].clips.empty() && !back.parts[0].clips.empty() && GetParam() != ".dae") {
        EXPECT_EQ(back.parts[0].clips.front().name, scene.parts[0].clips.front().name);
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, BlenderRig, testing::Values(".glb", ".fbx", ".dae"),
                         [](const testing::TestParamInfo<std::string>& format) {
                             return format.param.substr(1);
                         });

}  // namespace
}  // namespace rigmesh
