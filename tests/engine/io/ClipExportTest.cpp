// Clip export is bounded by the keys, not by the clip's length in frames
// (a key at 1e6 s, or 20,000 keys, once never finished).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "SharedSketchPart.h"
#include "io/AssimpAnimationBuilder.h"
#include "io/SceneExport.h"
#include "pose/Clip.h"

namespace rigmesh {
namespace {

TEST(ClipExport, ASmoothClipSpanningMillionsOfFramesSamplesEachSegmentBoundedly) {
    Clip clip;
    clip.interpolation = Interpolation::Smooth;
    clip.setKey(0.0, Pose{});
    clip.setKey(Clip::kLongestKeyTime, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    EXPECT_EQ(times.size(), 2u + kMaxFramesPerSegment);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
    EXPECT_EQ(times.front(), 0.0);
    EXPECT_EQ(times.back(), Clip::kLongestKeyTime);
}

TEST(ClipExport, ShortSmoothSegmentsStillGetEveryFrame) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Smooth;
    clip.setKey(0.0, Pose{});
    clip.setKey(1.0, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    EXPECT_EQ(times.size(), 25u);  // frames 0..24
    EXPECT_NEAR(times[12], 0.5, 1e-12);
}

TEST(ClipExport, TwentyThousandKeysGiveAtMostBoundedSamplesPerKey) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Smooth;
    for (int k = 0; k < 20000; ++k)
        clip.setKey(k * 0.5, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    // Twelve frames per half-second segment: the key and eleven between.
    EXPECT_EQ(times.size(), 19999u * 12u + 1u);
    EXPECT_TRUE(std::is_sorted(times.begin(), times.end()));
}

TEST(ClipExport, AConstantClipIsSampledEveryFrameSoTheStepSurvives) {
    Clip clip(24.0);
    clip.interpolation = Interpolation::Constant;
    clip.setKey(0.0, Pose{});
    clip.setKey(0.5, Pose{});
    const std::vector<double> times = exportedKeyTimes(clip);
    EXPECT_EQ(times.size(), 13u);  // frames 0..12
}

// Two parts with an "idle" and a "walk" clip each (and one unnamed clip):
// the clips of one name are one glTF animation over both parts' bones.
TEST(ClipExport, ClipsOfOneNameAcrossPartsAreOneAnimation) {
    const Part& a = testsupport::sharedSketchPart("tube");
    const Part& b = testsupport::sharedSketchPart("y_branch");
    auto clipNamed = [](const std::string& name, double end) {
        Clip clip(24.0);
        clip.name = name;
        clip.setKey(0.0, Pose{});
        clip.setKey(end, Pose{});
        return clip;
    };
    const Clip idleA = clipNamed("idle", 1.0), walkA = clipNamed("walk", 0.5);
    const Clip idleB = clipNamed("idle", 2.0), walkB = clipNamed("walk", 0.5);
    const Clip unnamed = clipNamed("", 1.0);
    std::vector<ExportPart> parts(2);
    parts[0].part = &a;
    parts[0].name = "a";
    parts[0].clip = &idleA;
    parts[0].otherClips = {&walkA};
    parts[1].part = &b;
    parts[1].name = "b";
    parts[1].clip = &walkB;
    parts[1].otherClips = {&idleB, &unnamed};
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / "rigmesh_clip_export_test";
    std::filesystem::create_directories(folder);
    const std::filesystem::path path = folder / "clips.gltf";
    exportScene(parts, nullptr, path.string());
    std::ifstream file(path);
    const nlohmann::json gltf = nlohmann::json::parse(file);
    std::map<std::string, std::set<std::string>> armatures;  // animation -> node name prefixes
    for (const auto& animation : gltf["animations"])
        for (const auto& channel : animation["channels"]) {
            const std::string node = gltf["nodes"][channel["target"]["node"].get<int>()]["name"];
            armatures[animation["name"]].insert(node.substr(0, node.find("_bone")));
        }
    EXPECT_EQ(armatures.size(), 3u);
    EXPECT_EQ(armatures["idle"], (std::set<std::string>{"a", "b"}));
    EXPECT_EQ(armatures["walk"], (std::set<std::string>{"a", "b"}));
    EXPECT_EQ(armatures["b_clip"], (std::set<std::string>{"b"}));
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace rigmesh
