// Keys lie at 0 s or later (pose/Clip.h): a file whose clip starts before
// 0 s (glTF allows it; Blender writes one for an action keyed at negative
// frames) is imported with the clip moved as a whole to start at 0 s.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>

#include "IoTestSupport.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

std::string fileText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(ClipImport, AClipStartingBeforeZeroIsMovedToStartAtZero) {
    const Part& part = iotest::sharedPart("y_branch");
    const Clip clip = poseDemoClip(part);  // keys at 0, 0.5 and 1 s
    const std::filesystem::path folder = iotest::scratchFolder();
    const std::filesystem::path path = folder / "early.gltf";
    ExportPart item;
    item.part = &part;
    exportScene({item}, &clip, path.string());

    // Every animation input 1.25 s earlier: the file's clip runs from -1.25 s.
    nlohmann::json gltf = nlohmann::json::parse(fileText(path));
    const std::filesystem::path binPath = folder / gltf["buffers"][0]["uri"].get<std::string>();
    std::string bin = fileText(binPath);
    std::set<int> inputs;
    for (const auto& animation : gltf["animations"])
        for (const auto& sampler : animation["samplers"])
            inputs.insert(sampler["input"].get<int>());
    ASSERT_FALSE(inputs.empty());
    for (int input : inputs) {
        nlohmann::json& accessor = gltf["accessors"][input];
        const auto& view = gltf["bufferViews"][accessor["bufferView"].get<int>()];
        const std::size_t offset =
            view.value("byteOffset", std::size_t{0}) + accessor.value("byteOffset", std::size_t{0});
        for (int k = 0; k < accessor["count"].get<int>(); ++k) {
            float time;
            std::memcpy(&time, bin.data() + offset + 4 * k, 4);
            time -= 1.25f;
            std::memcpy(bin.data() + offset + 4 * k, &time, 4);
        }
        accessor["min"] = {accessor["min"][0].get<float>() - 1.25f};
        accessor["max"] = {accessor["max"][0].get<float>() - 1.25f};
    }
    std::ofstream(binPath, std::ios::binary) << bin;
    std::ofstream(path) << gltf.dump();

    const ImportedScene scene = importScene(path.string());
    ASSERT_EQ(scene.parts.size(), 1u);
    ASSERT_EQ(scene.parts[0].clips.size(), 1u);
    const std::vector<double> times = scene.parts[0].clips.front().keyTimes();
    ASSERT_FALSE(times.empty());
    EXPECT_EQ(times.front(), 0.0);
    EXPECT_NEAR(times.back(), 1.0, 1e-5) << "the spacing is kept";
    for (double time : times)
        EXPECT_GE(time, 0.0);
    std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace rigmesh
