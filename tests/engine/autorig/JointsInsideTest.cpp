// A joint the curve skeleton put outside the surface is pulled back in
// along its bone (autorig/JointsInside).
#include <gtest/gtest.h>

#include "autorig/JointsInside.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

TEST(JointsInside, WindingNumberIsOneInsideAndZeroOutside) {
    const TriMesh rod = makeCylinderTube(16, 24, 0.3, 2.0);
    EXPECT_NEAR(windingNumber(rod, Vec3(0, 0, 0.5)), 1.0, 1e-6);
    EXPECT_NEAR(windingNumber(rod, Vec3(0, 0, 1.5)), 0.0, 1e-6);
    EXPECT_NEAR(windingNumber(rod, Vec3(0.5, 0, 0)), 0.0, 1e-6);
}

TEST(JointsInside, AJointBeyondTheTipMovesBackAlongItsBoneAndNothingElseMoves) {
    const TriMesh rod = makeCylinderTube(16, 24, 0.3, 2.0);  // z from -1 to 1
    Skeleton skeleton;
    const JointId root = skeleton.addJoint(Vec3(0, 0, -0.5));
    const JointId middle = skeleton.addJoint(Vec3(0, 0, 0.3));
    const JointId tip = skeleton.addJoint(Vec3(0, 0, 1.4));  // 0.4 past the end
    skeleton.addBone(root, middle);
    skeleton.addBone(middle, tip);
    const int moved = pullJointsInside(skeleton, rod, [](JointId) { return 0.15; });
    EXPECT_EQ(moved, 1);
    const Vec3 pulled = skeleton.joint(tip).position;
    EXPECT_NEAR(pulled.head<2>().norm(), 0.0, 1e-9);  // still on the bone's line
    EXPECT_NEAR(pulled.z(), 1.0 - 0.15, 1e-6);        // the margin inside the cap
    EXPECT_EQ(skeleton.joint(root).position, Vec3(0, 0, -0.5));
    EXPECT_EQ(skeleton.joint(middle).position, Vec3(0, 0, 0.3));
}

}  // namespace
}  // namespace rigmesh
