#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/FbxSentinels.h"
#include "io/FbxSkinningType.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"

namespace rigmesh {
namespace {

using Bytes = std::vector<std::uint8_t>;
namespace fs = std::filesystem;

// The tube exported to `path` with `skinning`: the file's bytes.
Bytes exportTube(const fs::path& path, SkinningMethod skinning) {
    const Part& part = iotest::sharedPart("tube");
    ExportPart item;
    item.part = &part;
    ExportOptions options;
    options.skinning = skinning;
    exportScene({item}, nullptr, path.string(), options);
    std::ifstream in(path, std::ios::binary);
    return Bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(FbxSkinningType, TheSkinDeformerSaysLinearForLinearBlend) {
    const Bytes bytes =
        exportTube(iotest::scratchFolder() / "linear.fbx", SkinningMethod::LinearBlend);
    EXPECT_EQ(fbxSkinningTypes(bytes), std::vector<std::string>{"Linear"});
}

TEST(FbxSkinningType, TheSkinDeformerSaysDualQuaternionWhenChosen) {
    const fs::path path = iotest::scratchFolder() / "dual.fbx";
    const Bytes bytes = exportTube(path, SkinningMethod::DualQuaternion);
    // One Skin deformer (the tube's mesh) with one SkinningType: Assimp's
    // "Linear" replaced, not a second record beside it.
    EXPECT_EQ(fbxSkinningTypes(bytes), std::vector<std::string>{"DualQuaternion"});
    EXPECT_EQ(addFbxSentinels(bytes), bytes);  // every nested list still closed
    const ImportedScene scene = importScene(path.string());
    ASSERT_EQ(scene.parts.size(), 1u);
    EXPECT_EQ(scene.parts[0].part.mesh.vertices.size(),
              iotest::sharedPart("tube").mesh.vertices.size());
}

TEST(FbxSkinningType, SettingItAgainChangesOnlyTheType) {
    const Bytes linear =
        exportTube(iotest::scratchFolder() / "again.fbx", SkinningMethod::LinearBlend);
    const Bytes dual = withFbxSkinningType(linear, SkinningMethod::DualQuaternion);
    EXPECT_EQ(fbxSkinningTypes(dual), std::vector<std::string>{"DualQuaternion"});
    // "Linear" -> "DualQuaternion": the file grows by the longer string only.
    EXPECT_EQ(dual.size(), linear.size() + std::string("DualQuaternion").size() - 6);
    EXPECT_EQ(withFbxSkinningType(dual, SkinningMethod::LinearBlend), linear);
}

TEST(FbxSkinningType, RejectsWhatIsNotABinaryFbx) {
    const std::string text = "; FBX 7.4.0 project file";
    EXPECT_THROW(withFbxSkinningType(Bytes(text.begin(), text.end()), SkinningMethod::LinearBlend),
                 Error);
}

}  // namespace
}  // namespace rigmesh
