// Pieces worn at a limb's end ride on it (autorig/WornPieces): a neck (a
// cylinder along z, the body's piece) carrying a head (a sphere, a piece of
// its own) that wears two horns (thin cylinders, a piece each), with the
// skeleton the flow gives such a figure: the neck's chain to a joint in the
// middle of the head, from there one branch into each horn.
#include <gtest/gtest.h>

#include <cmath>

#include "PiecewiseMesh.h"
#include "autorig/WornPieces.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

using autorigtest::addPiece;

struct Figure : autorigtest::PiecewiseMesh {
    Skeleton skeleton;
    JointId root = kNoJoint;
    JointId head = kNoJoint;  // the junction in the middle of the head
    std::vector<JointId> hornTips;
};

// A horn of length `length` and radius `radius` leaving the head's top at
// x = 0.8 side along (side, 0, 1), normalised.
void addHorn(Figure& figure, double side, double length, double radius) {
    const Vec3 base(side * 0.8, 0, 6.6);
    const Vec3 along = Vec3(side, 0, 1).normalized();
    const Vec3 across = Vec3(1, 0, -side).normalized();
    addPiece(figure, makeCylinderTube(9, 12, radius, length), [=](const Vec3& v) {
        return Vec3(base + (v.z() + 0.5 * length) * along + v.x() * across + v.y() * Vec3::UnitY());
    });
    Skeleton& skeleton = figure.skeleton;
    const JointId middle = skeleton.addJoint(base + 0.5 * length * along);
    const JointId tip = skeleton.addJoint(base + 0.9 * length * along);
    skeleton.addBone(figure.head, middle);
    skeleton.addBone(middle, tip);
    figure.hornTips.push_back(tip);
}

// The neck from z = 0 to 4.2 (radius 0.5), the head a sphere of radius 1.5
// about z = 5.5, horns of `hornLength` leaving it up and out.
Figure hornedHead(double hornLength, double hornRadius = 0.2) {
    Figure figure;
    addPiece(figure, makeCylinderTube(9, 16, 0.5, 4.2),
             [](const Vec3& v) { return Vec3(v.x(), v.y(), v.z() + 2.1); });
    addPiece(figure, makeIcosphere(3, 1.5),
             [](const Vec3& v) { return Vec3(v.x(), v.y(), v.z() + 5.5); });
    Skeleton& skeleton = figure.skeleton;
    figure.root = skeleton.addJoint(Vec3(0, 0, 0.5));
    const JointId neck = skeleton.addJoint(Vec3(0, 0, 3.0));
    figure.head = skeleton.addJoint(Vec3(0, 0, 5.5));
    skeleton.addBone(figure.root, neck);
    skeleton.addBone(neck, figure.head);
    skeleton.setRoot(figure.root);
    addHorn(figure, 1.0, hornLength, hornRadius);
    addHorn(figure, -1.0, hornLength, hornRadius);
    return figure;
}

int leafCount(const Skeleton& skeleton) {
    int leaves = 0;
    for (const Joint& joint : skeleton.joints())
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) == 1)
            ++leaves;
    return leaves;
}

TEST(WornPieces, HornsOnAHeadRideOnItsLastBoneAndTheHeadEndsInOneLeaf) {
    Figure figure = hornedHead(1.6);
    ASSERT_EQ(leafCount(figure.skeleton), 2);
    const WornPiecesReport report =
        pruneWornPieces(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.limbEnds, 1);
    EXPECT_EQ(report.branchesPruned, 2);
    const Skeleton& skeleton = figure.skeleton;
    EXPECT_TRUE(skeleton.validate().empty());
    for (JointId tip : figure.hornTips)
        EXPECT_FALSE(skeleton.hasJoint(tip));
    EXPECT_EQ(leafCount(skeleton), 1);
    // The head's joint goes on in one bone up to the crown, inside the head.
    ASSERT_EQ(skeleton.degree(figure.head), 2);
    for (const Joint& joint : skeleton.joints())
        if (joint.id != skeleton.root() && skeleton.degree(joint.id) == 1) {
            const Vec3& crown = joint.position;
            EXPECT_NEAR(crown.x(), 0.0, 1e-9);
            EXPECT_GT(crown.z(), 6.0);
            EXPECT_LT((crown - Vec3(0, 0, 5.5)).norm(), 1.5);
        }
}

// Horns reaching farther from the head than the coverage distance allows
// keep their bones, and nothing moves.
TEST(WornPieces, HornsReachingBeyondTheCoverageKeepTheirBones) {
    Figure figure = hornedHead(4.0);
    const Skeleton before = figure.skeleton;
    const WornPiecesReport report =
        pruneWornPieces(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_EQ(figure.skeleton.jointCount(), before.jointCount());
    for (const Joint& joint : before.joints())
        EXPECT_EQ(figure.skeleton.joint(joint.id).position, joint.position);
}

// Pieces as large as the end they leave (a pair of thick limbs) are limbs,
// not worn.
TEST(WornPieces, PiecesAsLargeAsTheEndTheyLeaveAreLimbs) {
    Figure figure = hornedHead(1.6, 0.9);
    const WornPiecesReport report =
        pruneWornPieces(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_EQ(leafCount(figure.skeleton), 2);
}

// Pieces leaving a body whose chain goes on past them (wings on a back, legs
// of a spider) are limbs: the horned piece here is the body, the root in it.
TEST(WornPieces, PiecesOnAPieceThatHoldsTheRootAreLimbs) {
    Figure figure = hornedHead(1.6);
    Skeleton& skeleton = figure.skeleton;
    // The root moves into the head: the head is the body now.
    skeleton.setJointPosition(figure.root, Vec3(0, 0, 4.6));
    const WornPiecesReport report =
        pruneWornPieces(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_EQ(leafCount(skeleton), 2);
}

// Five small pieces at one end (a glove's separate fingers) are limbs: no
// more than three pieces are worn at one end.
TEST(WornPieces, FiveSmallPiecesAtOneEndAreFingersNotWorn) {
    Figure figure = hornedHead(1.6);
    for (double side : {0.5, -0.5, 0.2})
        addHorn(figure, side, 1.6, 0.1);
    ASSERT_EQ(leafCount(figure.skeleton), 5);
    const WornPiecesReport report =
        pruneWornPieces(figure.skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_EQ(leafCount(figure.skeleton), 5);
}

// One small piece at a limb's end (a glove, a shoe of its own) is the
// limb's hand or foot: its bone stays.
TEST(WornPieces, ASinglePieceAtALimbsEndIsItsOwnHandOrFoot) {
    Figure figure = hornedHead(1.6);
    Skeleton& skeleton = figure.skeleton;
    // The second horn's chain goes: one branch is left, into one piece.
    const JointId tip = figure.hornTips.back();
    const Bone& last = skeleton.bone(skeleton.bonesAt(tip).front());
    const JointId middle = last.head == tip ? last.tail : last.head;
    skeleton.removeJoint(tip);
    skeleton.removeJoint(middle);
    ASSERT_EQ(skeleton.degree(figure.head), 2);
    const Skeleton before = skeleton;
    const WornPiecesReport report =
        pruneWornPieces(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_EQ(skeleton.jointCount(), before.jointCount());
    EXPECT_TRUE(skeleton.hasJoint(figure.hornTips.front()));
}

// A fork into a horn and a branch that stays in the head (an ear, a jaw
// of the head's own piece) is no limb end wearing pieces.
TEST(WornPieces, AForkWithABranchOfTheWearingPieceIsLeftAlone) {
    Figure figure = hornedHead(1.6);
    Skeleton& skeleton = figure.skeleton;
    const JointId jaw = skeleton.addJoint(Vec3(0, 0.9, 5.0));
    skeleton.addBone(figure.head, jaw);
    const WornPiecesReport report =
        pruneWornPieces(skeleton, figure.mesh, figure.pieceOf, figure.pieces, 3.0);
    EXPECT_EQ(report.branchesPruned, 0);
    EXPECT_TRUE(skeleton.hasJoint(jaw));
    for (JointId tip : figure.hornTips)
        EXPECT_TRUE(skeleton.hasJoint(tip));
}

}  // namespace
}  // namespace rigmesh
