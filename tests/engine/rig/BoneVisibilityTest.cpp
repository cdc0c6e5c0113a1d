// Which bones a vertex sees from inside the shape (Pinocchio's visibility,
// RigMesh section 2.4), and the point/segment helpers behind it.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include "BoneHeatTestMeshes.h"
#include "rig/BoneSegment.h"
#include "rig/BoneVisibility.h"

namespace rigmesh {
namespace {

// An L-shaped prism of height 1: the L (0,0) (2,0) (2,1) (1,1) (1,2) (0,2)
// leaves a concave notch at x, y in (1, 2). Vertices 0..5 at z = 0, 6..11 at
// z = 1; vertex 3 and 9 sit on the concave edge (1, 1, z).
TriMesh makeLPrism() {
    const std::vector<Vec2> outline = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
    TriMesh mesh;
    for (double z : {0.0, 1.0}) {
        for (const Vec2& p : outline) {
            mesh.vertices.emplace_back(p.x(), p.y(), z);
        }
    }
    // A fan from (0, 0) triangulates the L: every triangle stays inside it.
    for (int i = 1; i + 1 < 6; ++i) {
        mesh.faces.push_back({6, 6 + i, 6 + i + 1});  // top, facing +z
        mesh.faces.push_back({0, i + 1, i});          // bottom, facing -z
    }
    for (int i = 0; i < 6; ++i) {
        const int j = (i + 1) % 6;
        mesh.faces.push_back({i, j, 6 + j});
        mesh.faces.push_back({i, 6 + j, 6 + i});
    }
    return mesh;
}

// Inside the horizontal arm, inside the vertical arm, and outside in the notch.
const std::vector<BoneSegment> kLBones = {{Vec3(0.5, 0.5, 0.5), Vec3(1.75, 0.5, 0.5)},
                                          {Vec3(0.5, 0.5, 0.5), Vec3(0.5, 1.75, 0.5)},
                                          {Vec3(1.2, 1.2, 0.5), Vec3(1.9, 1.9, 0.5)}};

std::vector<int> bonesOf(const std::vector<std::pair<int, double>>& list) {
    std::vector<int> bones;
    for (const auto& entry : list) {
        bones.push_back(entry.first);
    }
    std::sort(bones.begin(), bones.end());
    return bones;
}

TEST(BoneSegment, ClosestPointIsClampedToTheEnds) {
    const BoneSegment bone{Vec3(0, 0, 0), Vec3(2, 0, 0)};
    EXPECT_NEAR(pointSegmentDistance(Vec3(1, 3, 0), bone), 3.0, 1e-15);
    EXPECT_NEAR(pointSegmentDistance(Vec3(-3, 4, 0), bone), 5.0, 1e-15);
    EXPECT_TRUE(closestPointOnSegment(Vec3(5, 1, 1), bone).isApprox(Vec3(2, 0, 0)));
}

TEST(BoneSegment, DegenerateBoneActsAsAPoint) {
    const BoneSegment point{Vec3(1, 1, 1), Vec3(1, 1, 1)};
    EXPECT_NEAR(pointSegmentDistance(Vec3(1, 1, 3), point), 2.0, 1e-15);
}

TEST(BoneSegment, NonFiniteBoneHasNonFiniteDistance) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const BoneSegment bone{Vec3(0, 0, 0), Vec3(nan, 0, 0)};
    EXPECT_FALSE(isFinite(bone));
    EXPECT_FALSE(std::isfinite(pointSegmentDistance(Vec3(1, 1, 1), bone)));
}

TEST(BoneVisibility, LPrismIsClosedAndOutward) {
    EXPECT_NEAR(test::signedVolume(makeLPrism()), 3.0, 1e-12);
}

TEST(BoneVisibility, SegmentFromAVertexIntoTheVolumeIsInside) {
    const BoneVisibility visibility(makeLPrism());
    EXPECT_TRUE(visibility.segmentIsInside(Vec3(0, 0, 0), Vec3(0.5, 0.5, 0.5)));
    EXPECT_TRUE(visibility.segmentIsInside(Vec3(1, 1, 0), Vec3(1, 0.5, 0.5)));
}

TEST(BoneVisibility, SegmentCrossingTheNotchWallIsNotInside) {
    const BoneVisibility visibility(makeLPrism());
    EXPECT_FALSE(visibility.segmentIsInside(Vec3(0, 2, 0), Vec3(1.2, 1.2, 0.5)));
    EXPECT_FALSE(visibility.segmentIsInside(Vec3(2, 0, 1), Vec3(0.5, 1.75, 0.5)));
}

TEST(BoneVisibility, BoneOutsideTheConcaveNotchIsNotVisible) {
    const TriMesh mesh = makeLPrism();
    const BoneVisibility visibility(mesh);
    // The notch bone is the closest from the concave edge, but it is outside:
    // the equally close inner bones of both arms are chosen instead.
    ASSERT_LT(pointSegmentDistance(mesh.vertices[3], kLBones[2]),
              pointSegmentDistance(mesh.vertices[3], kLBones[0]));
    int withoutVisible = -1;
    const auto closest =
        closestVisibleBones(mesh, kLBones, visibility, {3, 9, 0}, 1e-2, &withoutVisible);
    EXPECT_EQ(bonesOf(closest[0]), (std::vector<int>{0, 1}));
    EXPECT_EQ(bonesOf(closest[1]), (std::vector<int>{0, 1}));
    EXPECT_NEAR(closest[0][0].second, std::sqrt(0.5), 1e-12);
    EXPECT_EQ(bonesOf(closest[2]), (std::vector<int>{0, 1}));
    EXPECT_EQ(withoutVisible, 0);
}

TEST(BoneVisibility, NoVertexIsHeatedByTheBoneOutsideTheShape) {
    const TriMesh mesh = makeLPrism();
    const BoneVisibility visibility(mesh);
    std::vector<int> all(mesh.vertexCount());
    for (int v = 0; v < mesh.vertexCount(); ++v) {
        all[v] = v;
    }
    int withoutVisible = -1;
    const auto closest = closestVisibleBones(mesh, kLBones, visibility, all, 1e-2, &withoutVisible);
    EXPECT_EQ(withoutVisible, 0);
    for (const auto& list : closest) {
        ASSERT_FALSE(list.empty());
        for (const auto& entry : list) {
            EXPECT_NE(entry.first, 2);
        }
    }
}

TEST(BoneVisibility, VertexSeeingNoBoneFallsBackToTheClosestAndIsCounted) {
    const TriMesh tube = test::makeCappedTube(5, 8, 0.5, 2.0);
    const BoneVisibility visibility(tube);
    // One bone entirely outside the tube, one far away and also outside.
    const std::vector<BoneSegment> bones = {{Vec3(0, 2, 0), Vec3(2, 2, 0)},
                                            {Vec3(0, 5, 0), Vec3(2, 5, 0)}};
    int withoutVisible = -1;
    const auto closest =
        closestVisibleBones(tube, bones, visibility, {0, 1, 2}, 1e-2, &withoutVisible);
    EXPECT_EQ(withoutVisible, 3);
    for (const auto& list : closest) {
        EXPECT_EQ(bonesOf(list), std::vector<int>{0});
    }
}

TEST(BoneVisibility, NanBoneIsNeverChosen) {
    const TriMesh mesh = makeLPrism();
    const BoneVisibility visibility(mesh);
    std::vector<BoneSegment> bones = kLBones;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    bones.insert(bones.begin(), BoneSegment{Vec3(nan, 0, 0), Vec3(1, 1, 1)});
    const auto closest = closestVisibleBones(mesh, bones, visibility, {3});
    EXPECT_EQ(bonesOf(closest[0]), (std::vector<int>{1, 2}));
}

TEST(BoneVisibility, SkinWeightsOfTheLPrismIgnoreTheOutsideBone) {
    const TriMesh mesh = makeLPrism();
    const SkinWeights weights = computeBoneHeatWeights(mesh, kLBones);
    test::expectPartitionOfUnity(weights, mesh.vertexCount(), 3);
    for (const auto& list : weights.perVertex) {
        for (const auto& entry : list) {
            EXPECT_NE(entry.first, 2);
        }
    }
}

}  // namespace
}  // namespace rigmesh
