// A bone's name comes back from our export exactly, also where the file had
// to name its node otherwise to keep node names unique (a bone named as its
// part, or as our `Armature` node): the exporter keeps the bone's own name
// beside the node (BoneTipHints.h: rigmesh_name) and our importer gives it
// back, in every rigged format.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "IoTestSupport.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

class BoneNamesRoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(BoneNamesRoundTrip, NamesThatMeetOtherNodesComeBackUnchanged) {
    Part part = iotest::sharedPart("y_branch");
    ASSERT_GE(part.skeleton.boneCount(), 3);
    const std::vector<std::string> wanted = {part.name, "Armature", "Bone.001"};
    for (int b = 0; b < part.skeleton.boneCount(); ++b)
        part.boneNames[part.skeleton.bones()[b].id] =
            b < 3 ? wanted[static_cast<std::size_t>(b)] : "bone " + std::to_string(b);
    const Clip clip = poseDemoClip(part);
    ExportPart item;
    item.part = &part;
    const std::string path = (iotest::scratchFolder() / ("names" + GetParam())).string();
    exportScene({item}, &clip, path);
    const ImportedScene back = importScene(path);
    ASSERT_EQ(back.parts.size(), 1u);
    ASSERT_FALSE(back.parts[0].needsRig) << back.message;
    std::set<std::string> before, after;
    for (const auto& [bone, name] : part.boneNames)
        before.insert(name);
    for (const auto& [bone, name] : back.parts[0].part.boneNames)
        after.insert(name);
    EXPECT_EQ(after, before);
    EXPECT_EQ(back.parts[0].clips.size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(Formats, BoneNamesRoundTrip,
                         testing::Values(".glb", ".gltf", ".fbx", ".dae"),
                         [](const testing::TestParamInfo<std::string>& test) {
                             return test.param.substr(1);
                         });

}  // namespace
}  // namespace rigmesh
