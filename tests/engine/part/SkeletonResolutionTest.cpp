// The skeleton of a sketch does not depend on the surface's resolution (paper
// 2.3 simplifies the chordal axis, which the edge length does not change):
// every shared sketch gets the same joints at the default edge length and at
// half of it. Once sections followed the local thickness, CDP on the
// resampled sections gave the biped a twelfth joint at the right shoulder.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

#include "PartTestSupport.h"

namespace rigmesh {
namespace {

struct SurfaceAndSkeleton {
    SketchToSurfaceResult surface;
    PartSkeleton skeleton;
};

SurfaceAndSkeleton build(const std::string& sketch, double edgeLength) {
    SketchToSurfaceOptions options;
    options.surface.targetEdgeLength = edgeLength;
    SurfaceAndSkeleton result;
    result.surface = sketchToSurface(testsupport::sharedSketchPoints(sketch), options);
    result.skeleton = buildSkeleton(result.surface.decomposition, result.surface.cylinders);
    return result;
}

class SkeletonResolution : public ::testing::TestWithParam<std::string> {};

TEST_P(SkeletonResolution, HalfTheEdgeLengthGivesTheSameJoints) {
    const SurfaceAndSkeleton coarse = build(GetParam(), 0.0);
    const double edge = coarse.surface.targetEdgeLength;
    const SurfaceAndSkeleton fine = build(GetParam(), 0.5 * edge);
    const Skeleton& a = coarse.skeleton.skeleton;
    const Skeleton& b = fine.skeleton.skeleton;
    ASSERT_GT(fine.surface.surface.mesh.vertexCount(), coarse.surface.surface.mesh.vertexCount());
    EXPECT_EQ(a.jointCount(), b.jointCount());
    EXPECT_EQ(a.boneCount(), b.boneCount());
    // Joints on chords and junctions stay put; an end joint in the middle of
    // a cap moves with the cap's slices, by less than one edge length.
    for (const Joint& joint : b.joints()) {
        double nearest = std::numeric_limits<double>::infinity();
        for (const Joint& other : a.joints())
            nearest = std::min(nearest, (joint.position - other.position).norm());
        EXPECT_LT(nearest, edge) << "joint " << joint.id << " at " << joint.position.transpose();
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SkeletonResolution,
                         ::testing::ValuesIn(parttest::goodSketches()),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
