// Our own sketches written as plain OBJ (no rig), imported through Assimp
// as a user's file would be, and rigged.
#include <gtest/gtest.h>

#include "AutoRigTestSupport.h"

namespace rigmesh {
namespace {

using autorigtest::importedSketch;

class AutoRigSketch : public ::testing::TestWithParam<std::string> {};

TEST_P(AutoRigSketch, LeafCountEqualsTheSketchedLimbCount) {
    const auto& sketch = importedSketch(GetParam());
    EXPECT_EQ(autorigtest::leafCount(sketch.rigged.part.skeleton),
              autorigtest::leafCount(sketch.sketched.skeleton));
}

TEST_P(AutoRigSketch, SkeletonIsATreeInsideTheSurface) {
    const Part& part = importedSketch(GetParam()).rigged.part;
    EXPECT_TRUE(part.skeleton.validate().empty());
    EXPECT_TRUE(part.skeleton.isOrientedFromRoot());
    EXPECT_EQ(autorigtest::bonePointsOutside(part), 0);
}

TEST_P(AutoRigSketch, RiggedPartIsValidClosedAndWeighted) {
    const Part& part = importedSketch(GetParam()).rigged.part;
    EXPECT_TRUE(part.validateSolid().empty());
    autorigtest::expectPositiveWeightsSummingToOne(part.weights.perVertex, part.mesh.vertexCount());
}

TEST_P(AutoRigSketch, DominantBoneIsTheClosestVisibleBoneForAtLeast95Percent) {
    EXPECT_GE(autorigtest::dominantIsClosestVisibleShare(importedSketch(GetParam()).rigged.part),
              0.95);
}

TEST_P(AutoRigSketch, AGoodMeshIsRiggedVertexForVertex) {
    const auto& sketch = importedSketch(GetParam());
    EXPECT_TRUE(sketch.rigged.repairs.empty());
    EXPECT_EQ(sketch.rigged.surfaceKind, RigSurface::Kind::Input);
    ASSERT_EQ(sketch.rigged.part.mesh.vertexCount(), sketch.imported.mesh.vertexCount());
    EXPECT_EQ(sketch.rigged.part.mesh.faces, sketch.imported.mesh.faces);
    for (int v = 0; v < sketch.imported.mesh.vertexCount(); ++v) {
        EXPECT_EQ(sketch.rigged.part.mesh.vertices[v], sketch.imported.mesh.vertices[v]);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, AutoRigSketch,
                         ::testing::ValuesIn(autorigtest::sketchesToRig()));

// The shared sketches with more than two limbs.
class AutoRigBranchingSketch : public ::testing::TestWithParam<std::string> {};

TEST_P(AutoRigBranchingSketch, RootIsABranchingJoint) {
    const Skeleton& skeleton = importedSketch(GetParam()).rigged.part.skeleton;
    ASSERT_GT(autorigtest::leafCount(skeleton), 2);
    EXPECT_GE(skeleton.degree(skeleton.root()), 3);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, AutoRigBranchingSketch,
                         ::testing::Values("biped", "star", "y_branch"));

}  // namespace
}  // namespace rigmesh
