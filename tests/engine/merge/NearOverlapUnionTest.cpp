// The union on the faces near the overlap gives CGAL's whole union (the
// same faces, loop and sources; positions bit for bit but where an edge
// crosses an edge, within rounding), or leaves it to the whole union where
// it cannot answer for sure; a merge's refusals are the same.
#include <random>

#include "MergeTestSupport.h"
#include "TestShapes.h"
#include "UnionComparison.h"
#include "merge/NearOverlapUnion.h"
#include "mesh/MeshChecks.h"

namespace rigmesh::mergetest {
namespace {

using testsupport::expectBothScopesAgree;

// Shared sketch parts placed at random about each other's joints: turned
// (as MergeRandom places them), where no edge of one meets an edge of the
// other and the meshes agree bit for bit; and in the sketch plane (as parts
// sketched in one view are merged), where both parts' edges lie in z = 0
// and cross there, and only those crossing points may be rounded apart.
TEST(NearOverlapUnion, RandomPlacementsGiveTheWholeUnionsMesh) {
    std::mt19937 random(20261129);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const std::vector<std::string> sketches{"biped",     "banana",     "tube",       "y_branch",
                                            "camel_leg", "camel_body", "camel_head", "star"};
    int answered = 0, movedTurned = 0, movedInPlane = 0;
    for (int trial = 0; trial < 40; ++trial) {
        const bool inPlane = trial % 2 == 1;
        const Part& target = sharedSketchPart(sketches[trial % sketches.size()]);
        Part dragged = sharedSketchPart(sketches[(trial / 3 + 1) % sketches.size()]);
        if (!inPlane)
            dragged = rotated(dragged, Vec3(unit(random), unit(random), unit(random)),
                              3.0 * unit(random));
        const Joint& anchor = target.skeleton.joints()[trial % target.skeleton.jointCount()];
        const Vec3 nudge(unit(random), unit(random), inPlane ? 0.0 : unit(random));
        dragged = translated(
            dragged, anchor.position + 0.3 * nudge - dragged.skeleton.joints().front().position);
        const std::string label = "trial " + std::to_string(trial);
        const double edge = trial % 4 < 2 ? 0.0 : 0.1;
        const int moved = expectBothScopesAgree(target.mesh, dragged.mesh, edge, label);
        (inPlane ? movedInPlane : movedTurned) += moved;
        if (unionNearOverlap(target.mesh, dragged.mesh))
            ++answered;
    }
    EXPECT_EQ(movedTurned, 0);
    // The near union answers for nearly all of them (else it saves nothing).
    EXPECT_GE(answered, 34);
    std::printf("near union answered %d of 40; in the plane %d vertices rounded apart\n", answered,
                movedInPlane);
}

TriMesh moved(TriMesh mesh, const Eigen::Matrix3d& turn, const Vec3& offset) {
    for (Vec3& p : mesh.vertices)
        p = turn * p + offset;
    return mesh;
}

const Eigen::Matrix3d kStanding = Eigen::AngleAxisd(0.5 * M_PI, Vec3::UnitX()).toRotationMatrix();

// Two rings standing across each other cross in two loops, each ring's tube
// cut twice; the pieces inside are reached across the loops.
TEST(NearOverlapUnion, RingsCrossingInTwoLoopsGiveTheWholeUnionsMesh) {
    const TriMesh lying = testshapes::torus(48, 16, 1.0, 0.3);
    const TriMesh standing =
        moved(testshapes::torus(40, 14, 1.0, 0.3), kStanding, Vec3(0.5, 0.013, 0.007));
    ASSERT_TRUE(unionNearOverlap(lying, standing));
    expectBothScopesAgree(lying, standing, 0.0, "rings");
    expectBothScopesAgree(lying, standing, 0.1, "rings remeshed");
}

// A small ring within the other's box has no far faces: the side of its
// pieces comes from a ray cast to the other surface.
TEST(NearOverlapUnion, APartWithinTheOthersBoxIsToldByARay) {
    const TriMesh big = testshapes::torus(48, 16, 1.0, 0.4);
    const TriMesh small = moved(testshapes::torus(24, 10, 0.3, 0.09), Eigen::Matrix3d::Identity(),
                                Vec3(1.01, 0.02, 0.3));
    ASSERT_TRUE(boundingBox(big).contains(boundingBox(small)));
    ASSERT_TRUE(unionNearOverlap(big, small));
    expectBothScopesAgree(big, small, 0.0, "small in big");
    expectBothScopesAgree(small, big, 0.0, "big on small");
}

// Boxes sharing the planes of two sides (coplanar faces) and a box whose
// edges meet the other's faces on their diagonals: the first is left to the
// whole union, the second is a plain crossing; both give its mesh.
TEST(NearOverlapUnion, CoplanarFacesAreLeftToTheWholeUnion) {
    const TriMesh a = testshapes::box(Vec3(0, 0, 0), Vec3(2, 2, 2));
    const TriMesh flush = testshapes::box(Vec3(1, 1, 0), Vec3(3, 3, 2));
    EXPECT_FALSE(unionNearOverlap(a, flush));
    expectBothScopesAgree(a, flush, 0.0, "flush boxes");
    const TriMesh through = testshapes::box(Vec3(1, 0.5, 0.5), Vec3(3, 1.5, 1.5));
    expectBothScopesAgree(a, through, 0.0, "box through a side");
}

// A part inside the other or apart from it (their boxes overlapping) has no
// loop: the whole union refuses it, with the same message either way.
TEST(NearOverlapUnion, APartInsideOrApartIsRefusedAsByTheWholeUnion) {
    const TriMesh ring = testshapes::torus(48, 16, 1.0, 0.4);
    const TriMesh inside =
        moved(testshapes::torus(24, 10, 0.1, 0.05), kStanding, Vec3(1.0, 0.0, 0.0));
    EXPECT_FALSE(unionNearOverlap(ring, inside));
    expectBothScopesAgree(ring, inside, 0.0, "inside");
    const TriMesh inTheHole = testshapes::torus(24, 10, 0.2, 0.1);
    EXPECT_FALSE(unionNearOverlap(ring, inTheHole));
    expectBothScopesAgree(ring, inTheHole, 0.0, "apart");
    // A tilted box's faces reach into the boxes of a small one inside it
    // and of one outside it: near faces on both sides, but no loop.
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(0.8, Vec3(1, 1, 1).normalized()).toRotationMatrix();
    const TriMesh big =
        moved(testshapes::box(Vec3::Constant(-2), Vec3::Constant(2)), tilt, Vec3::Zero());
    const TriMesh small = testshapes::box(Vec3::Constant(-0.3), Vec3::Constant(0.3));
    EXPECT_FALSE(unionNearOverlap(big, small));
    expectBothScopesAgree(big, small, 0.0, "tilted box around a small one");
    const TriMesh outside = moved(small, Eigen::Matrix3d::Identity(), Vec3(2.83, 1.10, -0.73));
    ASSERT_TRUE(boundingBox(big).contains(boundingBox(outside)));
    EXPECT_FALSE(unionNearOverlap(big, outside));
    expectBothScopesAgree(big, outside, 0.0, "small box beside a tilted one");
}

// Two vertices at one position (boxes touching at a corner): the whole
// union tells them by position, so the near union leaves it to that.
TEST(NearOverlapUnion, TwoVerticesAtOnePositionAreLeftToTheWholeUnion) {
    TriMesh corner = testshapes::box(Vec3::Zero(), Vec3::Constant(2));
    testshapes::append(corner, testshapes::box(Vec3::Constant(2), Vec3::Constant(3)));
    const Eigen::Matrix3d tilt =
        Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const TriMesh poking =
        moved(testshapes::box(Vec3::Zero(), Vec3::Ones()), tilt, Vec3(-0.3, -0.2, -0.25));
    EXPECT_FALSE(unionNearOverlap(corner, poking));
    expectBothScopesAgree(corner, poking, 0.0, "corner");
}

}  // namespace
}  // namespace rigmesh::mergetest
