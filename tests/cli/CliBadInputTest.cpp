// `rigmesh build` and `rigmesh run` on numbers out of range: each is refused
// with exit 1 and a message, quickly, and nothing is written.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "CliRunner.h"

namespace fs = std::filesystem;
using rigmesh::test::quoted;
using rigmesh::test::runCli;
using rigmesh::test::scratch;

namespace {

fs::path writeFile(const std::string& name, const std::string& text) {
    const fs::path path = scratch(name);
    std::ofstream(path) << text;
    return path;
}

TEST(CliBadNumbers, SketchNumberBeyondDoubleExitsOneWithAMessage) {
    const fs::path sketch =
        writeFile("huge_number.json", R"({"points": [[0, 0], [1e999, 0], [1, 1], [0, 1]]})");
    const auto result = runCli("build " + quoted(sketch));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("out of range"), std::string::npos) << result.err;
}

TEST(CliBadNumbers, RecipeNumberBeyondDoubleExitsOneWithAMessage) {
    const fs::path recipe = writeFile("huge_number_recipe.json",
                                      R"({"format": "rigmesh-recipe", "version": 1, "steps": [
            {"command": "sketch", "points": [[0, 0], [4, 0], [4, 1e999], [0, 1]]}]})");
    const fs::path out = scratch("huge_number_recipe.glb");
    fs::remove(out);
    const auto result = runCli("run " + quoted(recipe) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("out of range"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliBadNumbers, MaxInfluencesBeyondIntIsRefusedWithTheRange) {
    const fs::path out = scratch("huge_influences.glb");
    fs::remove(out);
    const auto result = runCli("build example --max-influences 1e300 -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("from 0 to"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliBadNumbers, TinyEdgeLengthIsRefusedWithTheSmallestAllowed) {
    const auto result = runCli("build example --edge-length 1e-9");
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("at least"), std::string::npos) << result.err;
}

TEST(CliBadNumbers, RecipeTinyEdgeLengthIsRefusedByTheEngine) {
    const fs::path recipe = writeFile("tiny_edge_recipe.json",
                                      R"({"format": "rigmesh-recipe", "version": 1, "steps": [
            {"command": "sketch", "points": [[0, 0], [4, 0], [4, 1], [0, 1]],
             "options": {"edgeLength": 1e-12}}]})");
    const auto result = runCli("run " + quoted(recipe) + " -o " + quoted(scratch("tiny.glb")));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("too small"), std::string::npos) << result.err;
}

TEST(CliBadNumbers, SketchNear1e40IsRefusedNotWrittenWithNan) {
    const fs::path sketch =
        writeFile("near_1e40.json",
                  R"({"points": [[0, 0], [4e40, 0], [4e40, 1e40], [2e40, 3e40], [0, 1e40]]})");
    const fs::path out = scratch("near_1e40.off");
    fs::remove(out);
    const auto result = runCli("build " + quoted(sketch) + " -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("sizes from"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

TEST(CliBadNumbers, SketchFarFromTheOriginIsRefusedInsteadOfHanging) {
    const fs::path sketch =
        writeFile("far_away.json", R"({"points": [[1e15, 1e15], [1e15, 1.000000000000004e15],
            [1.000000000000004e15, 1.000000000000004e15], [1.000000000000004e15, 1e15]]})");
    const auto result = runCli("build " + quoted(sketch));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("rigmesh: "), std::string::npos) << result.err;
}

// A surface crossing itself used to print "mesh checks: FAILED", write the
// mesh and exit 0.
TEST(CliBadSketch, ASurfaceThatWouldCrossItselfExitsOneAndWritesNothing) {
    const fs::path out = scratch("needle_crossing.obj");
    fs::remove(out);
    const auto result =
        runCli("build '" RIGMESH_TEST_DATA "/sketches/needle_crossing.json' -o " + quoted(out));
    EXPECT_EQ(result.exitCode, 1) << result.err;
    EXPECT_NE(result.err.find("intersect itself"), std::string::npos) << result.err;
    EXPECT_FALSE(fs::exists(out));
}

}  // namespace
