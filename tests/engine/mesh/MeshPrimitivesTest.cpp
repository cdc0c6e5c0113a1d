#include <gtest/gtest.h>
#include <stdexcept>

#include "mesh/MeshPrimitives.h"

namespace rigmesh {
namespace {

constexpr double kRadiusTolerance = 1e-12;

TEST(MeshPrimitives, IcosphereHasTheExpectedCountsAndAllVerticesOnTheSphere) {
    const double radius = 1.5;
    for (int subdivisions = 0; subdivisions <= 3; ++subdivisions) {
        const TriMesh mesh = makeIcosphere(subdivisions, radius);
        const int scale = 1 << (2 * subdivisions);  // 4^subdivisions
        EXPECT_EQ(mesh.faceCount(), 20 * scale);
        EXPECT_EQ(mesh.vertexCount(), 10 * scale + 2);
        for (const Vec3& v : mesh.vertices)
            EXPECT_NEAR(v.norm(), radius, kRadiusTolerance);
    }
}

TEST(MeshPrimitives, CylinderTubeSpansItsLengthAlongZ) {
    const TriMesh mesh = makeCylinderTube(3, 8, 0.25, 2.0);
    EXPECT_EQ(mesh.vertexCount(), 3 * 8 + 2);
    EXPECT_EQ(mesh.faceCount(), 2 * 8 * 3);
    double zMin = 0, zMax = 0;
    for (const Vec3& v : mesh.vertices) {
        zMin = std::min(zMin, v.z());
        zMax = std::max(zMax, v.z());
        EXPECT_LE(std::hypot(v.x(), v.y()), 0.25 + kRadiusTolerance);
    }
    EXPECT_DOUBLE_EQ(zMin, -1.0);
    EXPECT_DOUBLE_EQ(zMax, 1.0);
}

TEST(MeshPrimitives, InvalidParametersThrow) {
    EXPECT_THROW(makeIcosphere(-1, 1.0), std::logic_error);
    EXPECT_THROW(makeIcosphere(2, 0.0), std::logic_error);
    EXPECT_THROW(makeCylinderTube(1, 8, 1.0, 1.0), std::logic_error);
    EXPECT_THROW(makeCylinderTube(2, 2, 1.0, 1.0), std::logic_error);
    EXPECT_THROW(makeCylinderTube(2, 8, 1.0, -1.0), std::logic_error);
}

}  // namespace
}  // namespace rigmesh
