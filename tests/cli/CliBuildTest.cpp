// `rigmesh build` end to end: every good shared sketch becomes a mesh file and
// statistics; every bad one a one-line reason and a non-zero exit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "CliRunner.h"

namespace fs = std::filesystem;
using rigmesh::test::readWholeFile;
using rigmesh::test::runCli;
using rigmesh::test::scratch;

namespace {

const fs::path kSketches = RIGMESH_SHARED_SKETCHES;

std::vector<std::string> sketchNames(bool bad) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(kSketches)) {
        std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".json" && (stem.rfind("bad_", 0) == 0) == bad)
            names.push_back(stem);
    }
    std::sort(names.begin(), names.end());
    return names;
}

class GoodSketch : public testing::TestWithParam<std::string> {};
class BadSketch : public testing::TestWithParam<std::string> {};

TEST_P(GoodSketch, BuildsAMeshFileAndStatistics) {
    const fs::path mesh = scratch(GetParam() + ".off");
    const fs::path stats = scratch(GetParam() + ".json");
    const fs::path svg = scratch(GetParam() + ".svg");
    auto result = runCli("build '" + (kSketches / (GetParam() + ".json")).string() + "' -o '" +
                         mesh.string() + "' --stats '" + stats.string() + "' --debug-svg '" +
                         svg.string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_TRUE(result.err.empty()) << result.err;

    auto json = nlohmann::json::parse(readWholeFile(stats));
    EXPECT_GT(json["vertices"].get<int>(), 100);
    EXPECT_GT(json["faces"].get<int>(), 100);
    EXPECT_GT(json["ms_total"].get<double>(), 0.0);
    // Every stage is reported, the mesh checks too, and the total is their sum.
    double stageSum = 0;
    for (const char* stage :
         {"clean", "triangulate", "chordal_axis", "decompose", "cross_sections", "surface",
          "smoothing", "surface_checks", "skeleton", "weights", "mesh_checks"}) {
        ASSERT_TRUE(json["ms_stages"].contains(stage)) << stage;
        stageSum += json["ms_stages"][stage].get<double>();
    }
    EXPECT_EQ(json["ms_stages"].size(), 11u);
    EXPECT_NEAR(json["ms_total"].get<double>(), stageSum, 1e-6 * stageSum);
    EXPECT_GT(json["ms_stages"]["mesh_checks"].get<double>(), 0.0);
    EXPECT_EQ(json["mesh"]["degenerate_faces"].get<int>(), 0);
    EXPECT_TRUE(json["mesh"]["checks_passed"].get<bool>());
    EXPECT_NE(result.out.find("mesh checks: passed"), std::string::npos) << result.out;
    EXPECT_TRUE(json["mesh"]["closed"].get<bool>());
    EXPECT_TRUE(json["mesh"]["manifold"].get<bool>());
    EXPECT_EQ(json["mesh"]["genus"].get<int>(), 0);

    // The OFF header states the counts the statistics report.
    std::string off = readWholeFile(mesh);
    std::istringstream header(off);
    std::string magic;
    int vertices = 0, faces = 0;
    header >> magic >> vertices >> faces;
    EXPECT_EQ(magic, "OFF");
    EXPECT_EQ(vertices, json["vertices"].get<int>());
    EXPECT_EQ(faces, json["faces"].get<int>());
    EXPECT_NE(readWholeFile(svg).find("<svg"), std::string::npos);
}

TEST_P(BadSketch, FailsWithAOneLineReasonAndWritesNothing) {
    const fs::path mesh = scratch(GetParam() + ".obj");
    fs::remove(mesh);
    auto result = runCli("build '" + (kSketches / (GetParam() + ".json")).string() + "' -o '" +
                         mesh.string() + "'");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_EQ(result.err.rfind("rigmesh: ", 0), 0u) << result.err;
    EXPECT_EQ(std::count(result.err.begin(), result.err.end(), '\n'), 1) << result.err;
    EXPECT_FALSE(fs::exists(mesh));
}

std::string paramName(const testing::TestParamInfo<std::string>& info) {
    return info.param;
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, GoodSketch, testing::ValuesIn(sketchNames(false)),
                         paramName);
INSTANTIATE_TEST_SUITE_P(SharedSketches, BadSketch, testing::ValuesIn(sketchNames(true)),
                         paramName);

TEST(CliBuild, HelpAfterACommandPrintsThatCommandsOptions) {
    for (const std::string command : {"build", "run", "import", "export"}) {
        const auto help = runCli(command + " --help");
        EXPECT_EQ(help.exitCode, 0) << command << ": " << help.err;
        EXPECT_EQ(help.out.rfind("usage: rigmesh " + command, 0), 0u) << help.out;
        EXPECT_EQ(help.out.find("\n  run "), std::string::npos) << "only that command's part";
    }
    EXPECT_NE(runCli("build --help").out.find("--edge-length"), std::string::npos);
}

TEST(CliBuild, ExampleRunsWithoutTheSharedFolder) {
    auto result = runCli("example");
    EXPECT_EQ(result.exitCode, 0) << result.err;
    EXPECT_NE(result.out.find("vertices"), std::string::npos);
}

TEST(CliBuild, MissingFileIsAClearError) {
    auto result = runCli("build /nonexistent/sketch.json");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.err.find("sketch.json"), std::string::npos) << result.err;
}

TEST(CliBuild, UnknownOutputFormatIsAClearError) {
    auto result = runCli("build example -o " + scratch("x.xyz").string());
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.err.find(".obj"), std::string::npos) << result.err;
}

// On a full disk, .obj and .dae once exited 0 with a truncated file and
// .fbx aborted. `ulimit -f` with SIGXFSZ ignored makes writes past 2 KiB fail
// as on a full disk; every output must then exit 1 and keep the old file.
TEST(CliBuild, AFullDiskExitsOneAndKeepsThePreviousFiles) {
    const fs::path folder = scratch("full_disk");
    fs::remove_all(folder);
    fs::create_directories(folder);
    for (const std::string option : {"-o out.obj", "-o out.dae", "-o out.fbx", "-o out.glb",
                                     "-o out.ply", "--rig rig.json", "--debug-svg debug.svg"}) {
        const std::string arguments = "build example " + option;
        const std::string inFolder = "cd '" + folder.string() + "' && ";
        ASSERT_EQ(
            std::system((inFolder + "'" + RIGMESH_CLI + "' " + arguments + " >/dev/null").c_str()),
            0);
        const std::string file = option.substr(option.find(' ') + 1);
        const std::string previous = readWholeFile(folder / file);
        const std::string full = inFolder + "ulimit -f 4 && trap '' XFSZ && '" + RIGMESH_CLI +
                                 "' " + arguments + " >/dev/null 2>err.txt";
        const int status = std::system(full.c_str());
        EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << option;
        EXPECT_NE(readWholeFile(folder / "err.txt").find("rigmesh: cannot write"),
                  std::string::npos)
            << option << ": " << readWholeFile(folder / "err.txt");
        EXPECT_EQ(readWholeFile(folder / file), previous) << option;
        fs::remove(folder / "err.txt");
    }
    // Nothing but the outputs (and the companions) is left behind.
    for (const auto& entry : fs::directory_iterator(folder))
        EXPECT_NE(entry.path().filename().string().front(), '.') << entry.path();
}

TEST(CliBuild, UnknownCommandAndOptionAreUsageErrors) {
    EXPECT_EQ(runCli("frobnicate").exitCode, 2);
    EXPECT_EQ(runCli("build example --frobnicate").exitCode, 1);
}

}  // namespace

namespace {

TEST(CliRun, ExampleRecipeExportsAnAnimatedGlb) {
    const fs::path out = scratch("camel.glb");
    fs::remove(out);
    auto result = runCli("run '" + std::string(RIGMESH_RESOURCES) + "/recipes/camel.json' -o '" +
                         out.string() + "'");
    ASSERT_EQ(result.exitCode, 0) << result.err;
    EXPECT_GT(fs::file_size(out), 1000u);
}

TEST(CliRun, BadStepNamesTheStepAndWritesNothing) {
    const fs::path recipe = scratch("bad_recipe.json");
    {
        std::ofstream file(recipe);
        file << R"({"format": "rigmesh-recipe", "version": 1, "steps": [
            {"command": "sketch", "points": [[0, 0], [4, 0], [4, 1], [0, 1]], "name": "bar"},
            {"command": "pose", "part": "bar", "joint": 4242, "target": [0, 0, 0]}]})";
    }
    const fs::path out = scratch("bad_recipe.glb");
    fs::remove(out);
    auto result = runCli("run '" + recipe.string() + "' -o '" + out.string() + "'");
    EXPECT_EQ(result.exitCode, 1);
    EXPECT_NE(result.err.find("step 2 (pose)"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
