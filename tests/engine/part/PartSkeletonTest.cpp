// The skeleton of every shared sketch (paper 2.3): a valid tree hanging from
// its root, with every joint strictly inside the surface.
#include <gtest/gtest.h>

#include <string>

#include "MeshInside.h"
#include "PartTestSupport.h"

namespace rigmesh {
namespace {

// A generalized winding number above this is inside (1 inside, 0 outside).
constexpr double kInsideWindingNumber = 0.5;
// A joint must lie at least this far from the surface, relative to the
// bounding-box diagonal, so it is inside rather than on the skin.
constexpr double kMinimumJointDepth = 1e-3;

class PartSkeleton : public ::testing::TestWithParam<std::string> {
  protected:
    const Part& part() const { return parttest::sharedPart(GetParam()).part; }
};

TEST_P(PartSkeleton, IsAValidTreeWithAtLeastOneBone) {
    const Skeleton& skeleton = part().skeleton;
    for (const Message& problem : skeleton.validate())
        ADD_FAILURE() << problem;
    EXPECT_GE(skeleton.boneCount(), 1);
}

TEST_P(PartSkeleton, BonesPointAwayFromTheRoot) {
    EXPECT_TRUE(part().skeleton.isOrientedFromRoot());
}

TEST_P(PartSkeleton, EveryJointIsStrictlyInsideTheSurface) {
    const TriMesh& mesh = part().mesh;
    const double minimumDepth = kMinimumJointDepth * parttest::boundingBoxDiagonal(mesh);
    for (const Joint& joint : part().skeleton.joints()) {
        EXPECT_GT(parttest::windingNumber(mesh, joint.position), kInsideWindingNumber)
            << "joint " << joint.id << " at " << joint.position.transpose();
        EXPECT_GT(parttest::distanceToSurface(mesh, joint.position), minimumDepth)
            << "joint " << joint.id << " at " << joint.position.transpose();
    }
}

// The inside test itself: a point one bounding-box diagonal above each joint
// (off the sketch plane) is outside.
TEST_P(PartSkeleton, InsideTestRejectsPointsOutsideTheSurface) {
    const TriMesh& mesh = part().mesh;
    const double diagonal = parttest::boundingBoxDiagonal(mesh);
    for (const Joint& joint : part().skeleton.joints()) {
        const Vec3 above = joint.position + Vec3(0.0, 0.0, diagonal);
        EXPECT_LT(parttest::windingNumber(mesh, above), kInsideWindingNumber);
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, PartSkeleton,
                         ::testing::ValuesIn(parttest::goodSketches()),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
