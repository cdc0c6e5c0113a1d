// Least-Squares Meshes (paper 2.2, [Sorkine and Cohen-Or 2004]) on an
// icosphere: anchors hold, a system without anchors is refused, free
// vertices move.
#include <gtest/gtest.h>

#include <vector>

#include "base/Error.h"
#include "mesh/MeshPrimitives.h"
#include "surface/LeastSquaresMesh.h"

namespace rigmesh {
namespace {

constexpr int kSubdivisions = 3;
constexpr double kRadius = 1.0;
constexpr double kStiffAnchor = 1e6;
constexpr double kAnchorTolerance = 1e-6;
constexpr double kMinFreeMotion = 1e-3;  // of the radius: free vertices must visibly move

TEST(LeastSquaresMesh, StiffAnchorsKeepEveryVertex) {
    const TriMesh sphere = makeIcosphere(kSubdivisions, kRadius);
    const auto positions =
        leastSquaresMesh(sphere, std::vector<double>(sphere.vertices.size(), kStiffAnchor));
    ASSERT_EQ(positions.size(), sphere.vertices.size());
    for (std::size_t v = 0; v < positions.size(); ++v)
        EXPECT_LE((positions[v] - sphere.vertices[v]).norm(), kAnchorTolerance) << "vertex " << v;
}

TEST(LeastSquaresMesh, WithoutAnchorsThrows) {
    const TriMesh sphere = makeIcosphere(kSubdivisions, kRadius);
    EXPECT_THROW(leastSquaresMesh(sphere, std::vector<double>(sphere.vertices.size(), 0.0)), Error);
}

TEST(LeastSquaresMesh, FreeHalfMovesAndStaysFinite) {
    const TriMesh sphere = makeIcosphere(kSubdivisions, kRadius);
    std::vector<double> weights(sphere.vertices.size(), 0.0);
    for (std::size_t v = 0; v < weights.size(); ++v)
        if (sphere.vertices[v].z() > 0)
            weights[v] = 1.0;
    const auto positions = leastSquaresMesh(sphere, weights);
    ASSERT_EQ(positions.size(), sphere.vertices.size());
    int free = 0, moved = 0;
    for (std::size_t v = 0; v < positions.size(); ++v) {
        EXPECT_TRUE(positions[v].allFinite()) << "vertex " << v;
        if (weights[v] > 0)
            continue;
        ++free;
        moved += (positions[v] - sphere.vertices[v]).norm() > kMinFreeMotion * kRadius ? 1 : 0;
    }
    ASSERT_GT(free, 0);
    EXPECT_EQ(moved, free) << "free vertices that stayed put: " << free - moved;
}

}  // namespace
}  // namespace rigmesh
