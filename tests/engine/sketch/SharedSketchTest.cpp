// The sketches in the shared folder: every one reads, the bad ones are
// rejected for their own reason and the good ones clean into simple polygons.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "SketchTestSupport.h"
#include "base/Error.h"
#include "sketch/Sketch.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {
namespace {

std::string sharedSketch(const std::string& name) {
    return std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json";
}

std::vector<std::string> sharedSketchNames(bool bad) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(RIGMESH_SHARED_SKETCHES)) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".json" && (stem.rfind("bad_", 0) == 0) == bad) {
            names.push_back(stem);
        }
    }
    std::sort(names.begin(), names.end());
    return names;
}

TEST(SharedSketches, EveryFileReadsWithItsName) {
    const auto good = sharedSketchNames(false);
    const auto bad = sharedSketchNames(true);
    ASSERT_GE(good.size(), 5u);
    ASSERT_EQ(bad.size(), 5u);
    for (const auto* names : {&good, &bad}) {
        for (const std::string& name : *names) {
            SCOPED_TRACE(name);
            Sketch sketch;
            ASSERT_NO_THROW(sketch = readSketchFile(sharedSketch(name)));
            EXPECT_EQ(sketch.name, name);
            EXPECT_GE(sketch.points.size(), 2u);
        }
    }
}

TEST(SharedSketches, NanTokenReadsAsNonFiniteCoordinate) {
    const Sketch sketch = readSketchFile(sharedSketch("bad_nan"));
    ASSERT_EQ(sketch.points.size(), 4u);
    EXPECT_TRUE(std::isnan(sketch.points[2].x()));
    EXPECT_EQ(sketch.points[2].y(), 1.0);
}

std::string cleaningError(const std::string& name) {
    try {
        cleanStroke(readSketchFile(sharedSketch(name)).points);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

TEST(SharedSketches, EachBadSketchIsRejectedForItsOwnReason) {
    const std::string figureEight = cleaningError("bad_figure_eight");
    const std::string nan = cleaningError("bad_nan");
    const std::string tooFew = cleaningError("bad_too_few_points");
    const std::string line = cleaningError("bad_degenerate_line");
    const std::string duplicates = cleaningError("bad_duplicates");
    EXPECT_NE(figureEight.find("crosses itself near ("), std::string::npos) << figureEight;
    EXPECT_NE(nan.find("Point 2"), std::string::npos) << nan;
    EXPECT_NE(nan.find("not a finite number"), std::string::npos) << nan;
    EXPECT_NE(tooFew.find("only 2 distinct points"), std::string::npos) << tooFew;
    EXPECT_NE(line.find("straight line"), std::string::npos) << line;
    EXPECT_NE(duplicates.find("only 3 distinct positions"), std::string::npos) << duplicates;
    EXPECT_NE(duplicates.find("repeat"), std::string::npos) << duplicates;
}

TEST(SharedSketches, EveryGoodSketchCleansIntoASimpleUniformCounterClockwisePolygon) {
    for (const std::string& name : sharedSketchNames(false)) {
        SCOPED_TRACE(name);
        const Sketch sketch = readSketchFile(sharedSketch(name));
        CleanPolygon clean;
        ASSERT_NO_THROW(clean = cleanStroke(sketch.points));
        EXPECT_GE(clean.points.size(), 60u);
        EXPECT_LE(clean.points.size(), 250u);
        expectSimpleCounterClockwise(clean.points);
        expectUniformSpacing(clean, 1.6);
    }
}

}  // namespace
}  // namespace rigmesh
