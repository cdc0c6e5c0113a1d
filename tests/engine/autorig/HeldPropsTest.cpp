// A prop gripped in a fist is one chain on from the hand (autorig/HeldProps):
// an arm (a cylinder along x, its end the fist) holding a staff (a thin
// cylinder along z through the fist, low on its shaft), as separate pieces
// of one mesh, with the skeleton the flow gives such a figure: the arm's
// chain to a joint in the fist, from there one branch down to the staff's
// lower end and one up to its top.
#include <gtest/gtest.h>

#include "PiecewiseMesh.h"
#include "autorig/HeldProps.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

using autorigtest::addPiece;

struct Figure : autorigtest::PiecewiseMesh {
    Skeleton skeleton;
    JointId hand = kNoJoint;
    JointId staffTop = kNoJoint;
    JointId staffBottom = kNoJoint;
};

// The arm from x = 0 to 4 (radius 0.5); the staff at x = 3.8 from z =
// `bottom` to z = 5 (radius 0.1), or in two pieces split at the fist.
Figure armHoldingStaff(double bottom, bool staffInTwoPieces = false) {
    Figure figure;
    // makeCylinderTube runs along z: turned a quarter about y, it runs along x.
    addPiece(figure, makeCylinderTube(9, 16, 0.5, 4.0),
             [](const Vec3& v) { return Vec3(v.z() + 2.0, v.y(), -v.x()); });
    const auto staff = [&](double from, double to) {
        addPiece(figure, makeCylinderTube(17, 8, 0.1, to - from), [=](const Vec3& v) {
            return Vec3(v.x() + 3.8, v.y(), v.z() + 0.5 * (from + to));
        });
    };
    if (staffInTwoPieces) {
        staff(bottom, -0.2);
        staff(0.2, 5.0);
    } else {
        staff(bottom, 5.0);
    }
    Skeleton& skeleton = figure.skeleton;
    const JointId shoulder = skeleton.addJoint(Vec3(0.2, 0, 0));
    const JointId elbow = skeleton.addJoint(Vec3(2.0, 0, 0));
    // The flow's junction sits off the staff's axis, above the fist's middle.
    figure.hand = skeleton.addJoint(Vec3(3.6, 0, 0.15));
    const JointId staffMiddle = skeleton.addJoint(Vec3(3.8, 0, 2.5));
    figure.staffTop = skeleton.addJoint(Vec3(3.8, 0, 4.8));
    figure.staffBottom = skeleton.addJoint(Vec3(3.8, 0, bottom + 0.2));
    skeleton.addBone(shoulder, elbow);
    skeleton.addBone(elbow, figure.hand);
    skeleton.addBone(figure.hand, staffMiddle);
    skeleton.addBone(staffMiddle, figure.staffTop);
    skeleton.addBone(figure.hand, figure.staffBottom);
    skeleton.setRoot(shoulder);
    return figure;
}

TEST(HeldProps, AStaffThroughAFistIsOneChainOnFromTheHand) {
    Figure figure = armHoldingStaff(-1.0);
    const HeldPropsReport report =
        pruneHeldProps(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 1);
    EXPECT_EQ(report.branchesPruned, 1);
    const Skeleton& skeleton = figure.skeleton;
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_FALSE(skeleton.hasJoint(figure.staffBottom));
    ASSERT_TRUE(skeleton.hasJoint(figure.staffTop));
    EXPECT_EQ(skeleton.degree(figure.staffTop), 1);
    EXPECT_EQ(skeleton.degree(figure.hand), 2);
    // The hand's joint is the grip's pivot: on the staff's axis, in the fist.
    const Vec3 hand = skeleton.joint(figure.hand).position;
    EXPECT_NEAR(hand.x(), 3.8, 1e-6);
    EXPECT_NEAR(hand.y(), 0.0, 1e-6);
    EXPECT_LT(std::abs(hand.z()), 0.5);
}

// A staff held far from its lower end: that end lies farther from the
// hand than the coverage distance allows, so it keeps its bone.
TEST(HeldProps, AnEndReachingBeyondTheCoverageKeepsItsBone) {
    Figure figure = armHoldingStaff(-3.0);
    const Skeleton before = figure.skeleton;
    const HeldPropsReport report =
        pruneHeldProps(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 1);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_TRUE(figure.skeleton.hasJoint(figure.staffBottom));
    // Nothing moved, the hand's joint included.
    for (const Joint& joint : before.joints())
        EXPECT_EQ(figure.skeleton.joint(joint.id).position, joint.position);
}

// Two branches into two different pieces (horns on a head, a leg each)
// are limbs of their own, not the two ends of one prop.
TEST(HeldProps, BranchesIntoTwoPiecesAreNoGrip) {
    Figure figure = armHoldingStaff(-1.0, true);
    const HeldPropsReport report =
        pruneHeldProps(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 0);
    EXPECT_TRUE(figure.skeleton.hasJoint(figure.staffBottom));
    EXPECT_EQ(figure.skeleton.degree(figure.hand), 3);
}

// Two branches into the staff on the same side of the hand (both up it)
// are no grip: a fork, not a shaft passing through the fist.
TEST(HeldProps, TwoBranchesOnOneSideOfTheHandAreNoGrip) {
    Figure figure = armHoldingStaff(-1.0);
    Skeleton& skeleton = figure.skeleton;
    skeleton.removeJoint(figure.staffBottom);
    const JointId fork = skeleton.addJoint(Vec3(3.8, 0, 1.2));
    skeleton.addBone(figure.hand, fork);
    const Skeleton before = skeleton;
    const HeldPropsReport report =
        pruneHeldProps(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 0);
    EXPECT_EQ(skeleton.jointCount(), before.jointCount());
}

// A short, thick piece across the hand (a shoe under an ankle, with toe
// and heel either side) is no prop: a prop is long and thin.
TEST(HeldProps, AShortThickPieceIsNoProp) {
    Figure figure;
    addPiece(figure, makeCylinderTube(9, 16, 0.5, 4.0),
             [](const Vec3& v) { return Vec3(v.z() + 2.0, v.y(), -v.x()); });
    // A shoe 1.6 long and 0.4 thick (radius) along z through the arm's end.
    addPiece(figure, makeCylinderTube(9, 16, 0.4, 1.6),
             [](const Vec3& v) { return Vec3(v.x() + 3.8, v.y(), v.z() + 0.1); });
    Skeleton& skeleton = figure.skeleton;
    const JointId shoulder = skeleton.addJoint(Vec3(0.2, 0, 0));
    const JointId ankle = skeleton.addJoint(Vec3(3.6, 0, 0.0));
    const JointId toe = skeleton.addJoint(Vec3(3.8, 0, 0.8));
    const JointId heel = skeleton.addJoint(Vec3(3.8, 0, -0.6));
    skeleton.addBone(shoulder, ankle);
    skeleton.addBone(ankle, toe);
    skeleton.addBone(ankle, heel);
    skeleton.setRoot(shoulder);
    const HeldPropsReport report =
        pruneHeldProps(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 0);
    EXPECT_TRUE(skeleton.hasJoint(heel));
}

// The staff's lower end runs on into the body (a thigh of the arm's own
// piece, below the fist): removing it would take a joint of the body, so
// nothing goes and nothing moves.
TEST(HeldProps, AnEndThatRunsOnIntoTheBodyStays) {
    Figure figure = armHoldingStaff(-1.0);
    // The thigh: a cylinder along x at z = -1.5, of the arm's piece (0).
    const int offset = figure.mesh.vertexCount();
    const TriMesh thigh = makeCylinderTube(9, 16, 0.3, 2.0);
    for (const Vec3& v : thigh.vertices) {
        figure.mesh.vertices.push_back(Vec3(v.z() + 3.5, v.y(), -v.x() - 1.5));
        figure.pieceOf.push_back(0);
    }
    for (const auto& [a, b, c] : thigh.faces)
        figure.mesh.faces.push_back({a + offset, b + offset, c + offset});
    Skeleton& skeleton = figure.skeleton;
    const JointId inThigh = skeleton.addJoint(Vec3(3.8, 0, -1.5));
    skeleton.addBone(figure.staffBottom, inThigh);
    const Skeleton before = skeleton;
    const HeldPropsReport report =
        pruneHeldProps(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.branchesPruned, 0);
    for (const Joint& joint : before.joints()) {
        ASSERT_TRUE(skeleton.hasJoint(joint.id));
        EXPECT_EQ(skeleton.joint(joint.id).position, joint.position);
    }
}

// An axe: a flat round blade (its own piece) on the staff's top, which the
// flow splits at its two corners. The prop is one chain: the corner
// farther from the hand stays.
TEST(HeldProps, ABladeOnAHeldShaftKeepsOnlyItsFarthestCorner) {
    Figure figure = armHoldingStaff(-1.0);
    // A disc of radius 0.8 in the x-z plane, centred on the shaft at z = 4.5.
    addPiece(figure, makeCylinderTube(2, 24, 0.8, 0.2),
             [](const Vec3& v) { return Vec3(v.x() + 3.8, -v.z(), v.y() + 4.5); });
    Skeleton& skeleton = figure.skeleton;
    skeleton.setJointPosition(figure.staffTop, Vec3(3.8, 0, 4.3));
    // The near corner first: the rule keeps the farther, not the first.
    const JointId nearCorner = skeleton.addJoint(Vec3(4.4, 0, 4.3));
    const JointId farCorner = skeleton.addJoint(Vec3(3.3, 0, 4.9));
    skeleton.addBone(figure.staffTop, nearCorner);
    skeleton.addBone(figure.staffTop, farCorner);
    const HeldPropsReport report =
        pruneHeldProps(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 1.5);
    EXPECT_EQ(report.grips, 1);
    EXPECT_EQ(report.branchesPruned, 2);
    EXPECT_TRUE(skeleton.validate().empty());
    EXPECT_TRUE(skeleton.hasJoint(farCorner));
    EXPECT_FALSE(skeleton.hasJoint(nearCorner));
    int leaves = 0;
    for (const Joint& joint : skeleton.joints())
        leaves += skeleton.degree(joint.id) == 1 ? 1 : 0;
    EXPECT_EQ(leaves, 2);  // the shoulder and the blade's far corner
}

}  // namespace
}  // namespace rigmesh
