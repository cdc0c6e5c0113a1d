// The surface figures (mesh/SurfaceQuality): what they measure on
// shapes with known answers. Their values on every shared sketch and on
// random outlines are guarded in test_surface's SurfaceFigures.
#include <gtest/gtest.h>

#include <cmath>

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

}  // namespace
}  // namespace rigmesh
