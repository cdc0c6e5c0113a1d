// A bone turning past an Euler angle's end keeps its keys through FBX
// (io/FbxRotationCurves.h): Assimp's reader inserts keys of its own where an
// angle changes by 180 degrees or more between two keys.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/FbxRotationCurves.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"
#include "pose/Skinning.h"

namespace rigmesh {
namespace {

TEST(FbxRotationCurves, ABoneTurningPastAHalfTurnComesBackWithItsKeys) {
    const Part& part = iotest::sharedPart("tube");
    ASSERT_GT(part.skeleton.boneCount(), 0);
    const JointId turned = part.skeleton.bones().back().tail;
    // 0, 170 and 340 degrees about X: as Euler angles in [-180, 180] the last
    // step is 170 -> -20, a jump of 190 degrees.
    Clip clip;
    clip.interpolation = Interpolation::Linear;
    clip.name = "turn";
    for (int k = 0; k < 3; ++k) {
        Pose pose;
        pose.setRotation(
            turned, Eigen::Quaterniond(Eigen::AngleAxisd(k * 170.0 * M_PI / 180.0, Vec3::UnitX())));
        clip.setKey(0.5 * k, pose);
    }
    ExportPart item;
    item.part = &part;
    const std::string path = (iotest::scratchFolder() / "turn.fbx").string();
    exportScene({item}, &clip, path);
    const ImportedScene back = importScene(path);
    ASSERT_EQ(back.parts.size(), 1u);
    ASSERT_EQ(back.parts[0].clips.size(), 1u);
    const Clip& again = back.parts[0].clips.front();
    ASSERT_EQ(again.keyTimes().size(), 3u);
    // The same deformation at each key and halfway between (the shorter way
    // round, as the quaternions interpolate).
    const double size = iotest::meshSize(part.mesh);
    const std::vector<int> match =
        iotest::matchVertices(part.mesh.vertices, back.parts[0].part.mesh.vertices);
    for (double t : {0.0, 0.25, 0.5, 0.75, 1.0}) {
        const PosedMesh ours = posePart(part, clip.evaluate(t), {SkinningMethod::LinearBlend, 2});
        const PosedMesh theirs =
            posePart(back.parts[0].part, again.evaluate(t), {SkinningMethod::LinearBlend, 2});
        double worst = 0;
        for (std::size_t v = 0; v < match.size(); ++v)
            worst = std::max(worst, (ours.mesh.vertices[v] -
                                     theirs.mesh.vertices[static_cast<std::size_t>(match[v])])
                                        .norm());
        EXPECT_LE(worst, 1e-4 * size) << "at " << t << " s";
    }
}

TEST(FbxRotationCurves, BytesThatAreNoFbxAreRefused) {
    const std::string text = "not an FBX file at all, just some text";
    EXPECT_THROW(withContinuousFbxRotations(std::vector<std::uint8_t>(text.begin(), text.end())),
                 Error);
}

}  // namespace
}  // namespace rigmesh
