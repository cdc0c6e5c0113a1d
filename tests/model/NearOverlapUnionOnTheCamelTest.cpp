// The union on the faces near the overlap (merge/NearOverlapUnion.h) on the
// camel at the shipped recipe's last merge (what bench_merge times): the
// head on the body where the merge puts it, and nudged and turned about
// there, gives CGAL's whole union bit for bit, and the near union answers
// for the benchmark's merge itself.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "CamelLastMerge.h"
#include "UnionComparison.h"
#include "merge/NearOverlapUnion.h"

namespace rigmesh {
namespace {

TEST(NearOverlapUnionOnTheCamel, TheHeadOnTheBodyGivesTheWholeUnionsMesh) {
    const testsupport::CamelLastMerge& m = testsupport::lastCamelMerge();
    const Vec3 placed = mergeParts(m.body, m.head, m.request).draggedTranslation;
    TriMesh head = m.head.mesh;
    for (Vec3& p : head.vertices)
        p += placed;
    EXPECT_TRUE(unionNearOverlap(m.body.mesh, head)) << "the benchmark's merge left to CGAL";
    // Bit for bit here: the loops' crossings of the sketch plane round alike.
    EXPECT_EQ(testsupport::expectBothScopesAgree(m.body.mesh, head, m.request.edgeLength, "placed"),
              0);
    EXPECT_EQ(testsupport::expectBothScopesAgree(m.body.mesh, head, 0.0, "placed, raw seam"), 0);

    // Nudged along each axis and turned about the neck's top joint.
    const Vec3 pivot = m.body.skeleton.joint(m.request.join.targetJoint).position;
    int variant = 0;
    for (const Vec3& nudge :
         {Vec3(0.05, 0, 0), Vec3(-0.05, 0.03, 0), Vec3(0, -0.04, 0.02), Vec3(0.02, 0.02, -0.03)})
        for (double angle : {-0.2, 0.15}) {
            const Eigen::Matrix3d turn =
                Eigen::AngleAxisd(angle, Vec3(0.3, 0.2, 1.0).normalized()).toRotationMatrix();
            TriMesh moved = head;
            for (Vec3& p : moved.vertices)
                p = pivot + turn * (p - pivot) + nudge;
            EXPECT_EQ(testsupport::expectBothScopesAgree(m.body.mesh, moved, m.request.edgeLength,
                                                         "variant " + std::to_string(variant++)),
                      0);
        }
}

}  // namespace
}  // namespace rigmesh
