// OBJ (rest and posed), static meshes from elsewhere (needsRig), several
// parts, and clear errors that leave no partial file.
#include <gtest/gtest.h>

#include <unistd.h>

#include <fstream>
#include <functional>

#include "IoTestSupport.h"
#include "base/Error.h"
#include "io/PoseDemoClip.h"
#include "io/SceneExport.h"
#include "io/SceneImport.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/MeshWriter.h"
#include "pose/Skinning.h"

namespace rigmesh {
namespace {

namespace fs = std::filesystem;

std::string errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

int fileCount(const fs::path& folder) {
    return static_cast<int>(
        std::distance(fs::directory_iterator(folder), fs::directory_iterator()));
}

ExportPart item(const Part& part) {
    ExportPart out;
    out.part = &part;
    out.pose = restPose(part.skeleton);
    return out;
}

TEST(ObjExport, RestPoseImportsAsAStaticPartThatNeedsARig) {
    const Part& part = iotest::sharedPart("y_branch");
    const fs::path folder = iotest::scratchFolder();
    exportScene({item(part)}, nullptr, (folder / "y.obj").string());
    EXPECT_TRUE(fs::exists(folder / "y.obj"));
    EXPECT_TRUE(fs::exists(folder / "y.mtl"));
    EXPECT_EQ(fileCount(folder), 2);
    const ImportedScene scene = importScene((folder / "y.obj").string());
    ASSERT_EQ(scene.parts.size(), 1u);
    EXPECT_TRUE(scene.needsRig);
    EXPECT_TRUE(scene.parts[0].needsRig);
    EXPECT_EQ(scene.parts[0].part.skeleton.jointCount(), 0);
    EXPECT_NE(scene.message.find("rig"), std::string::npos);
    const TriMesh& back = scene.parts[0].part.mesh;
    ASSERT_EQ(back.vertexCount(), part.mesh.vertexCount());
    const auto match = iotest::matchVertices(part.mesh.vertices, back.vertices);
    for (std::size_t v = 0; v < match.size(); ++v)
        EXPECT_LE(
            (part.mesh.vertices[v] - back.vertices[static_cast<std::size_t>(match[v])]).norm(),
            1e-5 * iotest::meshSize(part.mesh));
}

TEST(ObjExport, CurrentPoseWritesTheSkinnedMesh) {
    const Part& part = iotest::sharedPart("tube");
    ExportPart posed = item(part);
    posed.pose = poseDemoBend(part);
    ExportOptions options;
    options.restPose = false;
    const fs::path path = iotest::scratchFolder() / "posed.obj";
    exportScene({posed}, nullptr, path.string(), options);
    const TriMesh expected = posePart(part, posed.pose).mesh;
    const TriMesh back = importScene(path.string()).parts.at(0).part.mesh;
    const auto match = iotest::matchVertices(expected.vertices, back.vertices);
    double worst = 0;
    for (std::size_t v = 0; v < match.size(); ++v)
        worst = std::max(
            worst,
            (expected.vertices[v] - back.vertices[static_cast<std::size_t>(match[v])]).norm());
    EXPECT_LT(worst, 1e-5 * iotest::meshSize(part.mesh));
}

TEST(SceneImport, AStaticClosedMeshFromElsewhereNeedsARig) {
    const fs::path path = iotest::scratchFolder() / "box.ply";
    writeMesh(makeIcosphere(1, 2.0), path.string());
    const ImportedScene scene = importScene(path.string());
    ASSERT_EQ(scene.parts.size(), 1u);
    EXPECT_TRUE(scene.needsRig);
    EXPECT_EQ(scene.parts[0].part.mesh.faceCount(), makeIcosphere(1, 2.0).faceCount());
    EXPECT_TRUE(scene.parts[0].part.weights.perVertex.empty());
    EXPECT_TRUE(scene.parts[0].clips.empty());
}

TEST(SceneImport, MissingBrokenAndUnsupportedFilesGiveClearErrors) {
    const fs::path folder = iotest::scratchFolder();
    EXPECT_NE(errorOf([&] { importScene((folder / "none.glb").string()); }).find("no such file"),
              std::string::npos);
    std::ofstream(folder / "broken.glb") << "glTF this is not";
    std::ofstream(folder / "notes.xyz123") << "hello";
    const std::string broken = errorOf([&] { importScene((folder / "broken.glb").string()); });
    EXPECT_NE(broken.find("broken.glb"), std::string::npos) << broken;
    const std::string unsupported =
        errorOf([&] { importScene((folder / "notes.xyz123").string()); });
    EXPECT_NE(unsupported.find("notes.xyz123"), std::string::npos) << unsupported;
}

TEST(SceneExport, UnknownExtensionAndBadFolderLeaveNoFile) {
    const Part& part = iotest::sharedPart("tube");
    const fs::path folder = iotest::scratchFolder();
    const std::string unknown =
        errorOf([&] { exportScene({item(part)}, nullptr, (folder / "t.stl").string()); });
    EXPECT_NE(unknown.find(".glb"), std::string::npos) << unknown;
    const std::string missing =
        errorOf([&] { exportScene({item(part)}, nullptr, (folder / "no/such/t.glb").string()); });
    EXPECT_NE(missing.find("does not exist"), std::string::npos) << missing;
    fs::create_directory(folder / "t.glb");
    EXPECT_NE(errorOf([&] { exportScene({item(part)}, nullptr, (folder / "t.glb").string()); }),
              "");
    EXPECT_EQ(fileCount(folder), 1);  // only the folder made above: no partial or temporary file
}

TEST(SceneExport, AReadOnlyFolderIsAClearErrorAndLeavesNoFile) {
    const Part& part = iotest::sharedPart("tube");
    const fs::path folder = iotest::scratchFolder() / "locked";
    fs::create_directory(folder);
    fs::permissions(folder, fs::perms::owner_read | fs::perms::owner_exec);
    const std::string error =
        errorOf([&] { exportScene({item(part)}, nullptr, (folder / "t.fbx").string()); });
    fs::permissions(folder, fs::perms::owner_all);
    if (::geteuid() != 0) {  // root writes anyway
        EXPECT_NE(error.find("cannot write"), std::string::npos) << error;
    }
    EXPECT_EQ(fileCount(folder), error.empty() ? 1 : 0);
}

TEST(SceneExport, BadPartsAreClearErrors) {
    Part empty;
    empty.name = "empty";
    EXPECT_NE(errorOf([&] {
                  exportScene({item(empty)}, nullptr, (iotest::scratchFolder() / "e.glb").string());
              }).find("no surface"),
              std::string::npos);
    EXPECT_NE(
        errorOf([&] { exportScene({}, nullptr, (iotest::scratchFolder() / "e.glb").string()); }),
        "");
}

TEST(SceneExport, EachPartIsItsOwnSkinnedMeshWithItsOwnClip) {
    const Part& tube = iotest::sharedPart("tube");
    const Part& branch = iotest::sharedPart("y_branch");
    ExportPart a = item(tube), b = item(branch), c = item(tube);
    b.placement = Eigen::Translation3d(3, 0, 0) * Eigen::AngleAxisd(0.5, Vec3::UnitZ());
    Clip tubeClip = poseDemoClip(tube), branchClip = poseDemoClip(branch);
    branchClip.name = "wave";
    a.clip = &tubeClip;
    b.clip = &branchClip;
    for (const char* extension : {".glb", ".fbx", ".dae"}) {
        const fs::path path = iotest::scratchFolder() / (std::string("three") + extension);
        exportScene({a, b, c}, nullptr, path.string());
        const ImportedScene scene = importScene(path.string());
        ASSERT_EQ(scene.parts.size(), 3u) << extension;
        EXPECT_FALSE(scene.needsRig) << scene.message;
        EXPECT_EQ(scene.parts[0].part.skeleton.boneCount(), tube.skeleton.boneCount());
        EXPECT_EQ(scene.parts[1].part.skeleton.boneCount(), branch.skeleton.boneCount());
        // Unique names: the second tube's bones are tube_2_bone<id>.
        EXPECT_EQ(scene.parts[2].boneNames.at(0).rfind("tube_2_bone", 0), 0u);
        // Each animated part has its own clip, with its name; the third none.
        ASSERT_FALSE(scene.parts[0].clips.empty()) << extension;
        ASSERT_FALSE(scene.parts[1].clips.empty()) << extension;
        EXPECT_TRUE(scene.parts[2].clips.empty()) << extension;
        EXPECT_EQ(scene.parts[0].clips.front().keyCount(), tubeClip.keyCount()) << extension;
        EXPECT_EQ(scene.parts[1].clips.front().keyCount(), branchClip.keyCount()) << extension;
        if (std::string(extension) != ".dae") {  // Assimp's COLLADA pair drops names
            EXPECT_EQ(scene.parts[0].clips.front().name, "tube_clip");
            EXPECT_EQ(scene.parts[1].clips.front().name, "wave");
        }
        // The placement is baked into the second part's joints.
        const Vec3 root = branch.skeleton.joint(branch.skeleton.root()).position;
        const Skeleton& placed = scene.parts[1].part.skeleton;
        EXPECT_LE((placed.joint(placed.root()).position - b.placement * root).norm(), 1e-5);
    }
}

}  // namespace
}  // namespace rigmesh
