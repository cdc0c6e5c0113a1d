// The surface figures of issue 10 (mesh/SurfaceQuality): what they measure on
// shapes with known answers, and today's values on every shared sketch, which
// must not get worse (issue 10's targets, p99 <= 20 and max <= 35 degrees and
// IoU >= 0.95, are not met yet: the numbers are printed for that work).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "PartTestSupport.h"
#include "mesh/MeshPrimitives.h"
#include "mesh/SurfaceQuality.h"

namespace rigmesh {
namespace {

std::vector<Vec2> circle(double radius, int count = 256) {
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i)
        points.emplace_back(radius * std::cos(2 * M_PI * i / count),
                            radius * std::sin(2 * M_PI * i / count));
    return points;
}

TEST(SurfaceQuality, ASmoothSphereHasSmallNormalAnglesAndTheCircleAsSilhouette) {
    const TriMesh sphere = makeIcosphere(3, 1.0);
    const NormalAngles angles = normalAngles(sphere);
    EXPECT_EQ(angles.edges, 3 * sphere.faceCount() / 2);
    EXPECT_LT(angles.max, 10.0);
    EXPECT_GT(angles.p50, 1.0);
    EXPECT_GT(silhouetteIoU(sphere, circle(1.0)), 0.98);
    // Half the radius: a quarter of the area, all of it inside.
    EXPECT_NEAR(silhouetteIoU(sphere, circle(0.5)), 0.25, 0.02);
}

TEST(SurfaceQuality, ACoarseSphereCreasesMore) {
    EXPECT_GT(normalAngles(makeIcosphere(0, 1.0)).max, 30.0);
}

class SharedSketchSurface : public testing::TestWithParam<std::string> {};

TEST_P(SharedSketchSurface, CreasesAndSilhouetteNoWorseThanMeasured) {
    const SketchToPartResult& result = parttest::sharedPart(GetParam());
    const NormalAngles angles = normalAngles(result.part.mesh);
    const double iou = silhouetteIoU(result.part.mesh, result.surface.polygon.points);
    std::printf("%s: %d vertices, normal angles p50 %.1f p99 %.1f max %.1f degrees, IoU %.4f\n",
                GetParam().c_str(), result.part.mesh.vertexCount(), angles.p50, angles.p99,
                angles.max, iou);
    // Guards just past today's worst (measured 2026-11-24, after resolution
    // follows thickness, finer junction patches and held junction outlines:
    // p99 23.5 and max 53.6 on biped, at a junction seam; IoU 0.916 on
    // open_gap against the cleaned outline): crease and silhouette must not
    // get worse on any sketch.
    EXPECT_LE(angles.p99, 24.0);
    EXPECT_LE(angles.max, 54.5);
    EXPECT_GE(iou, 0.915);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SharedSketchSurface,
                         testing::ValuesIn(parttest::goodSketches()));

}  // namespace
}  // namespace rigmesh
