// Joints of a skeleton computed on a proxy moved into the mesh the part
// keeps, inside as ray-cast parity sees it (autorig/BonesInside
// keepJointsInMesh, autorig/SurfaceProbe InsideBy::RayParity).
#include <gtest/gtest.h>

#include "autorig/BonesInside.h"
#include "autorig/SurfaceProbe.h"
#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

TriMesh moved(TriMesh mesh, const Vec3& by) {
    for (Vec3& v : mesh.vertices)
        v += by;
    return mesh;
}

TriMesh joined(const TriMesh& a, const TriMesh& b) {
    TriMesh all = a;
    const int offset = all.vertexCount();
    all.vertices.insert(all.vertices.end(), b.vertices.begin(), b.vertices.end());
    for (const auto& [x, y, z] : b.faces)
        all.faces.push_back({x + offset, y + offset, z + offset});
    return all;
}

// A head with an eye inside it: two closed pieces, one in the other.
TriMesh headWithEye() {
    return joined(makeIcosphere(3, 1.0), moved(makeIcosphere(2, 0.2), Vec3(0.5, 0, 0)));
}

int leaves(const Skeleton& skeleton) {
    int count = 0;
    for (const Joint& joint : skeleton.joints())
        count += skeleton.degree(joint.id) == 1 ? 1 : 0;
    return count;
}

TEST(JointsInMesh, RayParityCallsAPointInsideAnEyeInsideAHeadOutside) {
    const TriMesh head = headWithEye();
    const SurfaceProbe parity(head, InsideBy::RayParity);
    const SurfaceProbe winding(head);
    EXPECT_FALSE(parity.inside(Vec3(0.5, 0, 0)));  // two walls each way
    EXPECT_TRUE(parity.inside(Vec3(-0.5, 0, 0)));
    EXPECT_TRUE(parity.inside(Vec3(0.5, 0.3, 0)));  // beside the eye
    EXPECT_FALSE(parity.inside(Vec3(1.2, 0, 0)));
    EXPECT_TRUE(winding.inside(Vec3(0.5, 0, 0)));  // winding number 2
}

TEST(JointsInMesh, WallsAlongARayCountASeamOnce) {
    // A ray through the sphere's vertex (0, 0, 1) meets five or six faces
    // there, one wall.
    const TriMesh sphere = makeIcosphere(2, 1.0);
    const SurfaceProbe probe(sphere, InsideBy::RayParity);
    Vec3 vertex = sphere.vertices.front();
    const std::vector<double> walls = probe.walls(Vec3::Zero(), vertex);
    ASSERT_EQ(walls.size(), 1u);
    EXPECT_NEAR(walls.front(), 1.0, 1e-9);
    EXPECT_EQ(probe.walls(-2.0 * vertex, vertex).size(), 2u);
}

// A face without area (two corners at one point under two vertex indices,
// as a file's split seams give) is no wall: Blender's ray casts and
// check_tails_inside_in_blender.py pass it by. The spider's fang
// (assimp-testmodels OBJ/spider.obj) has such faces at its tip; CGAL took
// them for segment hits along rays that pass beside them, and a joint
// outside the fang counted as inside.
TEST(JointsInMesh, WallsAlongARaySkipAFaceWithoutArea) {
    TriMesh mesh = moved(makeIcosphere(2, 1.0), Vec3(-60, 0, -18));  // a piece elsewhere
    const Vec3 tip(-66.59116, -11.97653, -20.11215);
    const int first = mesh.vertexCount();
    mesh.vertices.push_back(tip);
    mesh.vertices.push_back(Vec3(-67.36116, 2.86621, -14.54599));
    mesh.vertices.push_back(tip);
    mesh.faces.push_back({first, first + 1, first + 2});
    const SurfaceProbe probe(mesh, InsideBy::RayParity);
    const Vec3 beside(-67.530, -0.156, -18.856);  // 3.0 from that face's segment
    for (const Vec3& ray :
         {Vec3(0.267, 0.534, 0.802), Vec3(-0.7, 0.1, 0.3), Vec3(0.2, -0.9, -0.35)})
        EXPECT_TRUE(probe.walls(beside, ray).empty()) << ray.transpose();
    EXPECT_FALSE(probe.inside(beside));
    EXPECT_NEAR(probe.distance(Vec3(-60, 0, -16)), 1.0, 0.05);  // the sphere still counts
}

TEST(JointsInMesh, JointsOfAThinLimbInAFatProxyMoveIntoTheLimbKeepingTheTree) {
    const TriMesh limb = makeCylinderTube(24, 24, 0.1, 2.0);  // z from -1 to 1
    const TriMesh proxy = makeCylinderTube(24, 24, 0.3, 2.4);
    Skeleton skeleton;
    const JointId a = skeleton.addJoint(Vec3(0.2, 0, -0.6));
    const JointId b = skeleton.addJoint(Vec3(0.2, 0, 0));
    const JointId c = skeleton.addJoint(Vec3(0.15, 0.1, 0.6));
    const JointId tip = skeleton.addJoint(Vec3(0, 0, 1.1));  // beyond the limb's cap
    skeleton.addBone(a, b);
    skeleton.addBone(b, c);
    skeleton.addBone(c, tip);
    const JointsInMeshReport report = keepJointsInMesh(skeleton, limb, proxy, {0.1, 0.05, 1.0});
    EXPECT_EQ(report.jointsMoved, 4);
    EXPECT_EQ(report.jointsOutside, 0);
    const SurfaceProbe parity(limb, InsideBy::RayParity);
    for (const Joint& joint : skeleton.joints()) {
        EXPECT_TRUE(parity.inside(joint.position)) << joint.id;
        EXPECT_LT(joint.position.head<2>().norm(), 0.1 - 1e-4) << joint.id;
    }
    EXPECT_EQ(skeleton.boneCount(), 3);
    EXPECT_EQ(leaves(skeleton), 2);
    EXPECT_TRUE(skeleton.validate().empty());
    // Each joint stays at its height along the limb, the tip within the cap.
    EXPECT_NEAR(skeleton.joint(b).position.z(), 0.0, 0.1);
    EXPECT_GT(skeleton.joint(tip).position.z(), 0.6);
    EXPECT_LT(skeleton.joint(tip).position.z(), 1.0);
}

TEST(JointsInMesh, AJointInAnEyeMovesOutOfItIntoTheHead) {
    const TriMesh head = headWithEye();
    const TriMesh proxy = makeIcosphere(3, 1.1);
    Skeleton skeleton;
    const JointId eye = skeleton.addJoint(Vec3(0.5, 0, 0));
    const JointId back = skeleton.addJoint(Vec3(-0.5, 0, 0));
    skeleton.addBone(back, eye);
    const JointsInMeshReport report = keepJointsInMesh(skeleton, head, proxy, {0.1, 0.05, 2.0});
    EXPECT_EQ(report.jointsMoved, 1);
    EXPECT_EQ(report.jointsOutside, 0);
    const Vec3 p = skeleton.joint(eye).position;
    EXPECT_GT((p - Vec3(0.5, 0, 0)).norm(), 0.2);  // out of the eye
    EXPECT_TRUE(SurfaceProbe(head, InsideBy::RayParity).inside(p));
    EXPECT_EQ(skeleton.joint(back).position, Vec3(-0.5, 0, 0));
}

TEST(JointsInMesh, AJointWhereTheMeshHasNoInsideStays) {
    // A sheet (two triangles) in a proxy around it: no inside anywhere.
    TriMesh sheet;
    sheet.vertices = {Vec3(-1, -1, 0), Vec3(1, -1, 0), Vec3(1, 1, 0), Vec3(-1, 1, 0)};
    sheet.faces = {{0, 1, 2}, {0, 2, 3}};
    const TriMesh proxy = makeIcosphere(3, 1.6);
    Skeleton skeleton;
    const JointId a = skeleton.addJoint(Vec3(-0.5, 0, 0.01));
    const JointId b = skeleton.addJoint(Vec3(0.5, 0, 0.01));
    skeleton.addBone(a, b);
    const JointsInMeshReport report = keepJointsInMesh(skeleton, sheet, proxy, {0.1, 0.05, 2.0});
    EXPECT_EQ(report.jointsMoved, 0);
    EXPECT_EQ(report.jointsOutside, 2);
    EXPECT_EQ(skeleton.joint(a).position, Vec3(-0.5, 0, 0.01));
    EXPECT_EQ(skeleton.joint(b).position, Vec3(0.5, 0, 0.01));
}

}  // namespace
}  // namespace rigmesh
