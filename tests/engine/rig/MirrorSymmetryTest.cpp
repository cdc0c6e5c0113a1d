// Mirror symmetry (rig/MirrorSymmetry, rig/SkeletonSymmetry): the plane of a
// symmetric shape is found wherever it lies, an asymmetric one has none, a
// skeleton of a symmetric shape is made symmetric (mirrored branches get as
// many joints), and a symmetric outline sketched gives mirrored joints.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "SharedSketchPart.h"
#include "SymmetricOutline.h"
#include "pipeline/SketchToPart.h"
#include "rig/MirrorSymmetry.h"
#include "rig/SkeletonSymmetry.h"

namespace rigmesh {
namespace {

double diagonalOf(const std::vector<Vec3>& points) {
    Eigen::AlignedBox3d box;
    for (const Vec3& p : points)
        box.extend(p);
    return box.diagonal().norm();
}

// The biped's outline made exactly symmetric: its right half (x >= 0 about
// the middle of its box) and that half reflected. The half is taken from the
// part's closed outline, not the raw stroke: the stroke overshoots its start
// (its last points run back over its first ones on the right leg), which
// the sketch's closing trims but a plain reflection would keep as a fold.
std::vector<Vec2> symmetricBiped() {
    return testsupport::symmetricOutline(testsupport::sharedSketchPart("biped").outline);
}

TEST(MirrorPlane, IsFoundForASymmetricShapeTurnedAndMovedAnywhere) {
    const Part& star = testsupport::sharedSketchPart("y_branch");
    const Eigen::Affine3d moved = Eigen::Translation3d(3.0, -2.0, 7.0) *
                                  Eigen::AngleAxisd(0.7, Vec3(1.0, 2.0, 0.5).normalized());
    // The y_branch is symmetric front to back (its half surface mirrored
    // through z = 0): that plane, wherever the part is moved.
    TriMesh mesh = star.mesh;
    for (Vec3& v : mesh.vertices)
        v = moved * v;
    const std::optional<MirrorFit> fit = findMirrorPlane(mesh);
    ASSERT_TRUE(fit.has_value());
    EXPECT_LT(fit->error, 1e-3);
    const Vec3 expected = (moved.linear() * Vec3::UnitZ()).normalized();
    EXPECT_GT(std::abs(fit->plane.normal.dot(expected)), 1.0 - 1e-6);
    EXPECT_NEAR(expected.dot(fit->plane.point - moved.translation()), 0.0,
                1e-6 * diagonalOf(mesh.vertices));
}

// A scalene triangle (sides 3, about 1.3 and about 2.8) has no mirror line.
TEST(MirrorPlane, AnAsymmetricOutlineHasNoneInItsPlane) {
    const std::vector<Vec2> corners{Vec2(0.0, 0.0), Vec2(3.0, 0.0), Vec2(0.5, 1.2)};
    std::vector<Vec2> outline;
    for (int side = 0; side < 3; ++side)
        for (int i = 0; i < 40; ++i)
            outline.push_back(corners[side] +
                              (corners[(side + 1) % 3] - corners[side]) * (i / 40.0));
    MirrorSearch search;
    search.containing = Vec3::UnitZ();
    EXPECT_FALSE(findMirrorPlane(outlinePoints(outline), search).has_value());
}

TEST(MirrorPlane, ReflectedRotationsAreTheTurnSeenInTheMirror) {
    const MirrorPlane plane{Vec3(1.0, 0.0, 0.0), Vec3::UnitX()};
    const Eigen::Quaterniond q(Eigen::AngleAxisd(0.8, Vec3(0.3, 0.9, -0.2).normalized()));
    const Eigen::Quaterniond r = plane.reflectRotation(q);
    // M R M applied to any vector is the reflection of R applied to its
    // reflection.
    const Vec3 v(0.4, -1.2, 2.0);
    EXPECT_LT((r * v - plane.reflectDirection(q * plane.reflectDirection(v))).norm(), 1e-12);
}

// Paper 2.3 on a symmetric outline: the skeleton's joints come in mirrored
// pairs (or lie on the mirror), within 1% of the part's size.
TEST(SkeletonSymmetry, ASymmetricOutlineGivesMirroredJoints) {
    const std::vector<Vec2> outline = symmetricBiped();
    const Part part = sketchToPart(outline, "symmetric biped").part;
    MirrorSearch search;
    search.containing = Vec3::UnitZ();
    const std::optional<MirrorFit> fit = findMirrorPlane(outlinePoints(outline), search);
    ASSERT_TRUE(fit.has_value());
    const double size = diagonalOf(part.mesh.vertices);
    for (const Joint& joint : part.skeleton.joints()) {
        const Vec3 image = fit->plane.reflect(joint.position);
        double nearest = std::numeric_limits<double>::infinity();
        for (const Joint& other : part.skeleton.joints())
            nearest = std::min(nearest, (other.position - image).norm());
        EXPECT_LT(nearest, 0.01 * size) << "joint " << joint.id;
    }
    EXPECT_TRUE(part.validateSolid().empty());
}

// A skeleton whose mirrored limbs have one and two bones (as the curve
// skeleton gave a star's identical arms) gets two on both, mirrored.
TEST(SkeletonSymmetry, MirroredBranchesGetAsManyJointsAndMirroredPositions) {
    // A symmetric "V" of points about x = 0, as the surface to mirror.
    TriMesh shape;
    for (int i = 0; i <= 20; ++i) {
        const double t = i / 20.0;
        for (double side : {-1.0, 1.0})
            for (double dz : {-0.1, 0.0, 0.25})  // no symmetry front to back
                shape.vertices.emplace_back(side * (0.2 + t), t, dz);
    }
    Skeleton skeleton;
    const JointId root = skeleton.addJoint(Vec3(0.0, -0.1, 0.0));
    const JointId leftTip = skeleton.addJoint(Vec3(-1.2, 1.0, 0.0));
    const JointId rightElbow = skeleton.addJoint(Vec3(0.7, 0.52, 0.0));
    const JointId rightTip = skeleton.addJoint(Vec3(1.18, 1.02, 0.0));
    skeleton.addBone(root, leftTip);
    skeleton.addBone(root, rightElbow);
    skeleton.addBone(rightElbow, rightTip);
    const SymmetrizeReport report = symmetrizeSkeleton(skeleton, shape);
    ASSERT_TRUE(report.mirror.has_value());
    EXPECT_EQ(report.jointsAdded(), 1);
    EXPECT_EQ(skeleton.boneCount(), 4);
    EXPECT_TRUE(skeleton.validate().empty());
    for (const Joint& joint : skeleton.joints()) {
        const Vec3 image = report.mirror->plane.reflect(joint.position);
        double nearest = std::numeric_limits<double>::infinity();
        for (const Joint& other : skeleton.joints())
            nearest = std::min(nearest, (other.position - image).norm());
        EXPECT_LT(nearest, 1e-12) << "joint " << joint.id;
    }
    EXPECT_NEAR(skeleton.joint(root).position.x(), 0.0, 1e-12);
}

}  // namespace
}  // namespace rigmesh
