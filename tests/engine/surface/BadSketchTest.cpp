// Every bad_*.json sketch is rejected with a rigmesh::Error that explains
// why: never a crash, never another exception type.
#include <gtest/gtest.h>

#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

class BadSketch : public ::testing::TestWithParam<std::string> {};

TEST_P(BadSketch, IsRejectedWithAMessage) {
    try {
        sketchToSurface(readSketchFile(testsupport::sharedSketchPath(GetParam())).points);
        FAIL() << "no error for " << GetParam();
    } catch (const Error& error) {
        EXPECT_STRNE(error.what(), "");
    } catch (const std::exception& error) {
        FAIL() << "wrong exception type: " << error.what();
    } catch (...) {
        FAIL() << "a non-standard exception";
    }
}

TEST(BadSketches, AllFiveAreFound) {
    EXPECT_EQ(testsupport::sharedSketchNames(true).size(), 5u);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, BadSketch,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(true)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
