// Tails and connections of imported bones (io/BoneTails.h): from the file's
// flags and stated tails, the file's bone axis and children, or the
// vertices each bone leads, a guess kept inside the surface.
#include <gtest/gtest.h>

#include <cmath>

#include "autorig/JointsInside.h"
#include "io/BoneTails.h"

namespace rigmesh {
namespace {

// A frame whose +Y runs along `direction`.
Eigen::Matrix3d alongY(const Vec3& direction) {
    return Eigen::Quaterniond::FromTwoVectors(Vec3::UnitY(), direction.normalized())
        .toRotationMatrix();
}

TailBone bone(const Vec3& head, const Eigen::Matrix3d& axes, int parent) {
    TailBone b;
    b.head = head;
    b.axes = axes;
    b.parent = parent;
    return b;
}

// Blender's layout: a spine up +y with a neck on its axis and two
// shoulders off it, a leaf arm on each shoulder.
std::vector<TailBone> blenderTorso() {
    const Eigen::Matrix3d up = alongY(Vec3::UnitY());
    return {bone(Vec3(0, 0, 0), up, -1),                          // 0 spine
            bone(Vec3(0, 1, 0), up, 0),                           // 1 neck, on the spine's axis
            bone(Vec3(0.2, 0.9, 0), alongY(Vec3::UnitX()), 0),    // 2 shoulder.L
            bone(Vec3(-0.2, 0.9, 0), alongY(-Vec3::UnitX()), 0),  // 3 shoulder.R
            bone(Vec3(0.5, 0.9, 0), alongY(Vec3::UnitX()), 2),    // 4 arm.L, on its axis
            bone(Vec3(-0.5, 0.9, 0), alongY(-Vec3::UnitX()), 3)};
}

TEST(BoneTails, BlenderFilesConnectTheChildOnTheBonesAxis) {
    const BoneTailsResult result = guessBoneTails(blenderTorso(), {}, {}, 2.0);
    EXPECT_EQ(result.boneAxis, 2);  // +Y
    EXPECT_LE((result.tails[0] - Vec3(0, 1, 0)).norm(), 1e-12);
    EXPECT_TRUE(result.connected[1]);
    EXPECT_FALSE(result.connected[2]);
    EXPECT_FALSE(result.connected[3]);
    EXPECT_LE((result.tails[2] - Vec3(0.5, 0.9, 0)).norm(), 1e-12);
    EXPECT_TRUE(result.connected[4]);
    EXPECT_TRUE(result.connected[5]);
}

TEST(BoneTails, ALeafFollowsTheVerticesItLeads) {
    // The neck leads vertices up to y = 1.5 along its axis.
    std::vector<Vec3> vertices;
    std::vector<int> dominant;
    for (int k = 0; k <= 10; ++k) {
        vertices.push_back(Vec3(0.05, 1.0 + 0.05 * k, 0));
        dominant.push_back(1);
    }
    const BoneTailsResult result =
        guessBoneTails(blenderTorso(), TriMesh{vertices, {}}, dominant, 2.0);
    // Along the file's axis (+Y of the neck) to the 90th percentile of reach.
    EXPECT_NEAR(result.tails[1].y(), 1.45, 1e-9);
    EXPECT_NEAR(result.tails[1].x(), 0.0, 1e-12);
    // A leaf without vertices: its parent's length along its axis.
    EXPECT_LE((result.tails[4] - Vec3(0.8, 0.9, 0)).norm(), 1e-12);
}

TEST(BoneTails, StatedTailsAndFlagsComeFirst) {
    std::vector<TailBone> bones = blenderTorso();
    bones[1].connectFlag = false;  // a COLLADA file says the neck is not connected
    bones[0].statedTail = Vec3(0, 1.0, 0);
    bones[4].statedTail = Vec3(0.9, 0.9, 0);
    const BoneTailsResult result = guessBoneTails(bones, {}, {}, 2.0);
    EXPECT_FALSE(result.connected[1]);
    EXPECT_LE((result.tails[4] - Vec3(0.9, 0.9, 0)).norm(), 1e-12);

    bones[1].connectFlag = std::nullopt;
    bones[2].connectFlag = true;  // the shoulder is the connected child
    const BoneTailsResult flagged = guessBoneTails(bones, {}, {}, 2.0);
    EXPECT_LE((flagged.tails[0] - Vec3(0.2, 0.9, 0)).norm(), 1e-12);
    EXPECT_TRUE(flagged.connected[2]);
    EXPECT_FALSE(flagged.connected[1]);
}

TEST(BoneTails, DirectXFilesRunAlongX) {
    // 3ds Max / Maya layout: each bone's child along its local +X.
    const Eigen::Matrix3d turned =
        Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix();  // +X a little up
    const Vec3 x = turned.col(0);
    std::vector<TailBone> bones = {bone(Vec3::Zero(), turned, -1), bone(x, turned, 0),
                                   bone(2 * x, turned, 1), bone(x + Vec3(0, 0, 0.3), turned, 1)};
    const BoneTailsResult result = guessBoneTails(bones, {}, {}, 3.0);
    EXPECT_EQ(result.boneAxis, 0);  // +X
    EXPECT_LE((result.tails[1] - 2 * x).norm(), 1e-12);
    EXPECT_TRUE(result.connected[2]);
    EXPECT_FALSE(result.connected[3]);
    // A leaf without vertices: along +X, its parent's length.
    EXPECT_LE((result.tails[2] - 3 * x).norm(), 1e-12);
}

TEST(BoneTails, NoTailIsEverOnTheHead) {
    // A glTF leaf and a bone whose only child starts at its own head.
    const Eigen::Matrix3d up = Eigen::Matrix3d::Identity();
    std::vector<TailBone> bones = {bone(Vec3::Zero(), up, -1), bone(Vec3::Zero(), up, 0)};
    const BoneTailsResult result = guessBoneTails(bones, {}, {}, 1.0);
    for (std::size_t b = 0; b < bones.size(); ++b)
        EXPECT_GT((result.tails[b] - bones[b].head).norm(), 1e-3) << b;
    EXPECT_FALSE(result.connected[1]);  // it hangs at its parent's head
}

// A closed box (outward faces) around the segment from `from` along `axis`
// (unit) `length` long, `halfWidth` each side, its sides along `side` and
// axis x side.
TriMesh boxAround(const Vec3& from, const Vec3& axis, const Vec3& side, double length,
                  double halfWidth) {
    const Vec3 third = axis.cross(side);
    TriMesh box;
    for (int k = 0; k < 2; ++k)
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)  // corner i + 2j + 4k
                box.vertices.push_back(from + i * length * axis + (2 * j - 1) * halfWidth * side +
                                       (2 * k - 1) * halfWidth * third);
    box.faces = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    return box;
}

TEST(BoneTails, AGuessedTailStaysInsideTheSurface) {
    // The neck's limb leans 45 degrees off the neck's +Y (a limb the file's
    // bone does not follow, as Testwuson's leaves): the reach of the
    // vertices it leads, measured along +Y, ends far outside the limb.
    const Vec3 lean = Vec3(1, 1, 0).normalized();
    const TriMesh limb =
        boxAround(Vec3(0, 0.9, 0), lean, Vec3(-1, 1, 0).normalized(), std::sqrt(2.0) * 0.8, 0.15);
    const std::vector<int> dominant(limb.vertices.size(), 1);
    const double size = 2.0;
    ASSERT_GT(windingNumber(limb, blenderTorso()[1].head), 0.5);  // the head is inside

    const BoneTailsResult guessed =
        guessBoneTails(blenderTorso(), TriMesh{limb.vertices, {}}, dominant, size);
    EXPECT_NEAR(guessed.tails[1].y(), 1.7 + 0.15 / std::sqrt(2.0), 1e-9);  // a far corner
    EXPECT_LT(windingNumber(limb, guessed.tails[1]), 0.5);  // without the surface: outside

    const BoneTailsResult kept = guessBoneTails(blenderTorso(), limb, dominant, size);
    const Vec3 tail = kept.tails[1];
    EXPECT_GT(windingNumber(limb, tail), 0.5);
    // Along the bone, pulled back to where the +Y line leaves the leaning
    // box (y = 0.9 + 0.15 sqrt 2), 1e-4 of the size inside.
    EXPECT_NEAR(tail.x(), 0.0, 1e-12);
    EXPECT_NEAR(tail.z(), 0.0, 1e-12);
    const double leaves = 0.9 + 0.15 * std::sqrt(2.0);
    EXPECT_LT(tail.y(), leaves);
    EXPECT_NEAR(tail.y(), leaves - 1e-4 * size, 1e-6 * size);
    // Guesses already inside and the tails the file gives stay as they were.
    for (int b : {0, 2, 3, 4, 5})
        EXPECT_LE(
            (kept.tails[static_cast<std::size_t>(b)] - guessed.tails[static_cast<std::size_t>(b)])
                .norm(),
            1e-12)
            << b;
}

}  // namespace
}  // namespace rigmesh
