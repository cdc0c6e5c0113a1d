// Reading sketches from JSON text and from files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "base/Error.h"
#include "sketch/Sketch.h"

namespace rigmesh {
namespace {

std::string errorOf(const std::string& json) {
    try {
        parseSketchJson(json, "test.json");
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST(SketchJson, ReadsNameAndPointsInOrder) {
    const Sketch sketch = parseSketchJson(
        R"({"name": "blob", "description": "d", "points": [[0, 0], [1.5, -2], [3e2, 4]]})",
        "x.json");
    EXPECT_EQ(sketch.name, "blob");
    ASSERT_EQ(sketch.points.size(), 3u);
    EXPECT_EQ(sketch.points[1], Vec2(1.5, -2.0));
    EXPECT_EQ(sketch.points[2], Vec2(300.0, 4.0));
}

TEST(SketchJson, NameFallsBackToTheSourceFileStem) {
    const Sketch sketch = parseSketchJson(R"({"points": [[0, 0]]})", "/some/dir/my_sketch.json");
    EXPECT_EQ(sketch.name, "my_sketch");
}

TEST(SketchJson, BareNanAndInfinityTokensBecomeNonFiniteCoordinates) {
    const Sketch sketch = parseSketchJson(
        R"({"name":"NaN in a string stays text","points":[[NaN,1],[Infinity,-Infinity]]})",
        "t.json");
    EXPECT_EQ(sketch.name, "NaN in a string stays text");
    ASSERT_EQ(sketch.points.size(), 2u);
    EXPECT_TRUE(std::isnan(sketch.points[0].x()));
    EXPECT_EQ(sketch.points[1].x(), INFINITY);
    EXPECT_EQ(sketch.points[1].y(), -INFINITY);
}

TEST(SketchJson, NullCoordinateIsAnErrorNamingThePoint) {
    const std::string message = errorOf(R"({"points": [[0, 0], [1, null]]})");
    EXPECT_NE(message.find("point 1"), std::string::npos) << message;
    EXPECT_NE(message.find("null"), std::string::npos) << message;
}

TEST(SketchJson, StringCoordinateIsAnError) {
    const std::string message = errorOf(R"({"points": [["NaN", 0]]})");
    EXPECT_NE(message.find("must be a number"), std::string::npos) << message;
}

TEST(SketchJson, MalformedDocumentsGiveClearErrors) {
    EXPECT_NE(errorOf("{\"points\": [[0, 0],").find("not valid JSON"), std::string::npos);
    EXPECT_NE(errorOf("[[0, 0]]").find("JSON object"), std::string::npos);
    EXPECT_NE(errorOf(R"({"name": "x"})").find("no \"points\""), std::string::npos);
    EXPECT_NE(errorOf(R"({"points": [[0, 0, 0]]})").find("[x, y] pair"), std::string::npos);
    EXPECT_NE(errorOf(R"({"points": [5]})").find("[x, y] pair"), std::string::npos);
    EXPECT_NE(errorOf("").find("test.json"), std::string::npos);
}

TEST(SketchFile, UnknownExtensionIsAnError) {
    try {
        readSketchFile(std::string(RIGMESH_SHARED_SKETCHES) + "/star.txt");
        FAIL() << "expected an error";
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("unknown file type"), std::string::npos);
    }
}

TEST(SketchFile, MissingFileAndDirectoryAreErrors) {
    EXPECT_THROW(readSketchFile("/nonexistent/dir/sketch.json"), Error);
    const auto directory = std::filesystem::temp_directory_path() / "rigmesh_sketch_dir.json";
    std::filesystem::create_directories(directory);
    EXPECT_THROW(readSketchFile(directory.string()), Error);
    std::filesystem::remove(directory);
}

TEST(SketchFile, ExtensionIsCaseInsensitive) {
    EXPECT_THROW(readSketchFile("/nonexistent/SKETCH.SVG"), Error);
    try {
        readSketchFile("/nonexistent/SKETCH.SVG");
    } catch (const Error& error) {
        EXPECT_NE(std::string(error.what()).find("not readable"), std::string::npos);
    }
}

}  // namespace
}  // namespace rigmesh
