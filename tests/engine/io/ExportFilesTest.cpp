// Exported files are complete or untouched (full disk, read-only target),
// keep their permissions, leave no temporary file, and hold only defined
// bytes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "FullDisk.h"
#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/GltfBuffers.h"
#include "io/RigJson.h"
#include "io/SceneExport.h"
#include "part/BoneWeights.h"
#include "pose/Clip.h"

namespace rigmesh {
namespace {

using iotest::scratchFolder;
using rigmesh::fulldisk::FullDiskOutcome;
using rigmesh::fulldisk::runOnFullDisk;
namespace fs = std::filesystem;

std::string bytesOf(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

std::set<std::string> namesIn(const fs::path& folder) {
    std::set<std::string> names;
    for (const auto& entry : fs::directory_iterator(folder))
        names.insert(entry.path().filename().string());
    return names;
}

void exportBiped(const fs::path& path) {
    ExportPart item;
    item.part = &iotest::sharedPart("biped");
    exportScene({item}, nullptr, path.string());
}

class EveryFormat : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryFormat, AFullDiskIsAnErrorAndLeavesThePreviousFilesAndNoTemporaryFile) {
    const fs::path folder = scratchFolder();
    const fs::path target = folder / ("out." + GetParam());
    exportBiped(target);
    const std::set<std::string> before = namesIn(folder);
    std::map<std::string, std::string> contents;
    for (const std::string& name : before)
        contents[name] = bytesOf(folder / name);

    EXPECT_EQ(runOnFullDisk(4096, [&] { exportBiped(target); }), FullDiskOutcome::RefusedWithError);
    EXPECT_EQ(namesIn(folder), before);
    for (const std::string& name : before)
        EXPECT_EQ(bytesOf(folder / name), contents[name]) << name;
}

TEST_P(EveryFormat, ExportKeepsTheTargetsPermissionsAndRefusesAReadOnlyTarget) {
    const fs::path folder = scratchFolder();
    const fs::path target = folder / ("out." + GetParam());
    exportBiped(target);
    fs::permissions(target, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
    exportBiped(target);
    EXPECT_EQ(fs::status(target).permissions(),
              fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);

    fs::permissions(target, fs::perms::owner_read | fs::perms::group_read);
    const std::string previous = bytesOf(target);
    const std::set<std::string> before = namesIn(folder);
    try {
        exportBiped(target);
        ADD_FAILURE() << "a read-only target was replaced";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("read-only"), std::string::npos) << error.what();
    }
    EXPECT_EQ(bytesOf(target), previous);
    EXPECT_EQ(namesIn(folder), before);
}

INSTANTIATE_TEST_SUITE_P(Formats, EveryFormat,
                         ::testing::Values("glb", "gltf", "fbx", "dae", "obj"));

TEST(GlbExport, TwoIdenticalExportsAreByteIdenticalWithNoUndefinedBytes) {
    const fs::path folder = scratchFolder();
    exportBiped(folder / "a.glb");
    exportBiped(folder / "b.glb");
    const std::string a = bytesOf(folder / "a.glb");
    EXPECT_EQ(a, bytesOf(folder / "b.glb"));
    // Every byte outside the buffer views (Assimp's joint region) is zero.
    EXPECT_EQ(zeroUnreferencedGlbBytes(a), a);
}

TEST(GltfExport, TheBinHasAContentNameAndTheOldBinGoesOnlyAfterTheNewGltf) {
    const fs::path folder = scratchFolder();
    const fs::path target = folder / "walk.gltf";
    exportBiped(target);
    const std::string firstBin = bufferUriOf(bytesOf(target));
    EXPECT_TRUE(fs::exists(folder / firstBin)) << firstBin;
    EXPECT_NE(firstBin, "walk.bin");

    ExportPart item;
    item.part = &iotest::sharedPart("tube");
    exportScene({item}, nullptr, target.string());
    const std::string secondBin = bufferUriOf(bytesOf(target));
    EXPECT_NE(secondBin, firstBin);
    EXPECT_EQ(namesIn(folder), (std::set<std::string>{"walk.gltf", secondBin}));
}

TEST(SceneExport, NonFiniteKeyTimesNeverReachAFile) {
    Clip clip;
    EXPECT_THROW(clip.setKey(1e308, Pose{}), Error);
    // Within range, but 32-bit float times (glTF) cannot tell the keys apart.
    const Part& part = iotest::sharedPart("tube");
    // Floats are 1/16 s apart near 1e6 s; the keys are 1.2 half-frames apart.
    const double far = Clip::kLongestKeyTime - 1.0;
    clip.setKey(far, Pose{});
    clip.setKey(far + 1.2 * clip.keyTolerance(), Pose{});
    ASSERT_EQ(clip.keyCount(), 2);
    const fs::path folder = scratchFolder();
    ExportPart item;
    item.part = &part;
    EXPECT_THROW(exportScene({item}, &clip, (folder / "far.glb").string()), Error);
    EXPECT_TRUE(namesIn(folder).empty());
}

TEST(RigJson, NonFiniteWeightsOrJointsAreRefused) {
    Part part = iotest::sharedPart("tube");
    EXPECT_FALSE(rigToJson(part).empty());
    part.weights.perVertex[5].front().second = std::numeric_limits<double>::infinity();
    EXPECT_THROW(rigToJson(part), Error);
}

// The --rig file names joints and bones by their position in its lists (as
// glTF's skins do) and says so; the stable ids are written beside them, so
// a reader can tell them apart once ids skip numbers (a deleted bone).
TEST(RigJson, PositionsAndIdsAreBothWrittenAndTellApart) {
    Part part = iotest::sharedPart("y_branch");
    // Ids no longer equal positions: bone 0 and joint 0 go.
    Skeleton& skeleton = part.skeleton;
    const Bone first = skeleton.bones().front();
    const JointId leaf = skeleton.degree(first.head) == 1 ? first.head : first.tail;
    ASSERT_EQ(skeleton.degree(leaf), 1) << "the first bone ends at a leaf";
    skeleton.removeJoint(leaf);
    skeleton.setRoot(chooseCentralRoot(skeleton));
    skeleton.reorient();
    for (auto& list : part.weights.perVertex) {
        std::erase_if(list, [&](const auto& entry) { return entry.first == first.id; });
        if (list.empty())
            list.emplace_back(skeleton.bones().front().id, 1.0);
        normaliseWeights(list);
    }
    const nlohmann::json rig = nlohmann::json::parse(rigToJson(part));
    EXPECT_NE(rig["about"].get<std::string>().find("position"), std::string::npos);
    const auto& joints = rig["joints"];
    EXPECT_EQ(rig["root_id"], skeleton.root());
    EXPECT_EQ(joints[rig["root"].get<int>()]["id"], skeleton.root());
    ASSERT_EQ(rig["bones"].size(), static_cast<std::size_t>(skeleton.boneCount()));
    for (std::size_t b = 0; b < rig["bones"].size(); ++b) {
        const auto& bone = rig["bones"][b];
        const Bone& expected = skeleton.bones()[b];
        EXPECT_EQ(bone["id"], expected.id);
        EXPECT_EQ(bone["head_id"], expected.head);
        EXPECT_EQ(bone["tail_id"], expected.tail);
        EXPECT_EQ(joints[bone["head"].get<int>()]["id"], expected.head);
        EXPECT_EQ(joints[bone["tail"].get<int>()]["id"], expected.tail);
        const auto parent = skeleton.parentBone(expected.id);
        if (parent) {
            EXPECT_EQ(bone["parent_id"], *parent);
            EXPECT_EQ(rig["bones"][bone["parent"].get<int>()]["id"], *parent);
        } else {
            EXPECT_TRUE(bone["parent_id"].is_null());
            EXPECT_EQ(bone["parent"], -1);
        }
    }
    EXPECT_NE(rig["bones"][0]["id"], 0) << "the ids skip the deleted bone's";
}

}  // namespace
}  // namespace rigmesh
