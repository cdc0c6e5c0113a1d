// Our own sketches written as plain OBJ (no rig), imported through Assimp
// as a user's file would be, and rigged (issue 17 item 4).
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <iostream>

#include "AutoRigTestSupport.h"

namespace rigmesh {
namespace {

using autorigtest::ImportedSketch;
using autorigtest::importedSketch;

class AutoRigSketch : public ::testing::TestWithParam<std::string> {};

TEST_P(AutoRigSketch, Diagnostics) {
    const ImportedSketch& sketch = importedSketch(GetParam());
    const Part& rigged = sketch.rigged.part;
    std::cout << GetParam() << ": sketch leaves "
              << autorigtest::leafCount(sketch.sketched.skeleton) << " rig leaves "
              << autorigtest::leafCount(rigged.skeleton) << " bones " << rigged.skeleton.boneCount()
              << " vertices " << rigged.mesh.vertexCount() << " seconds " << sketch.seconds
              << " closest-visible share " << autorigtest::dominantIsClosestVisibleShare(rigged)
              << " outside " << autorigtest::bonePointsOutside(rigged) << "\n";
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, AutoRigSketch,
                         ::testing::ValuesIn(autorigtest::sketchesToRig()));

}  // namespace
}  // namespace rigmesh
