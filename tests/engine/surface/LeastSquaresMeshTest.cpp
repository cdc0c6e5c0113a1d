// Least-Squares Meshes (paper 2.2, [Sorkine and Cohen-Or 2004]) on an
// icosphere: anchors hold, a system without anchors is refused, free
// vertices move.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "SketchToSurfaceTestSupport.h"
#include "base/Error.h"
#include "mesh/MeshPrimitives.h"
#include "pipeline/SketchToSurface.h"
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

// A mirror-symmetric surface with mirror-symmetric weights (free, soft and
// held vertices by their distance along the sketch) is solved on half the
// unknowns when its mirror is given: the same positions as the full system
// within rounding, exactly mirrored. Weights that differ between a vertex
// and its image are solved in full, bit for bit as without the mirror.
TEST(LeastSquaresMesh, MirroredSurfaceIsSolvedOnHalfTheUnknownsWithTheFullSystemsPositions) {
    const SketchToSurfaceResult built =
        sketchToSurface(testsupport::sharedSketchPoints("y_branch"));
    const TriMesh& mesh = built.surface.mesh;
    const std::vector<int>& mirror = built.surface.mirror;
    double low = mesh.vertices.front().x(), high = low;
    for (const Vec3& p : mesh.vertices) {
        low = std::min(low, p.x());
        high = std::max(high, p.x());
    }
    constexpr double kHeld = 10.0;
    std::vector<double> weights(mesh.vertices.size());
    for (std::size_t v = 0; v < weights.size(); ++v) {
        const double along = (mesh.vertices[v].x() - low) / (high - low);
        weights[v] = along < 0.3 ? 0.0 : along < 0.6 ? 1.0 : kHeld;
    }
    const auto full = leastSquaresMesh(mesh, weights, kHeld);
    const auto half = leastSquaresMesh(mesh, weights, kHeld, mirror);
    ASSERT_EQ(half.size(), full.size());
    double largest = 0, moved = 0;
    for (std::size_t v = 0; v < full.size(); ++v) {
        largest = std::max(largest, (half[v] - full[v]).norm());
        moved = std::max(moved, (full[v] - mesh.vertices[v]).norm());
        const Vec3& image = half[mirror[v]];
        EXPECT_EQ(Vec3(image.x(), image.y(), -image.z()), half[v]) << "vertex " << v;
    }
    EXPECT_GT(moved, kMinFreeMotion);
    // Both are the one minimiser up to rounding, which the free third of the
    // part amplifies (L^T L's condition grows with the free region's size to
    // the fourth): 1.4e-11 here on a part 3.8 long. The sketch surfaces are
    // held to 1e-9 (their free regions are the junctions: 2e-13).
    EXPECT_LT(largest, 1e-9 * (high - low));

    std::vector<double> uneven = weights;
    int off = 0;
    while (mirror[off] == off || uneven[off] >= kHeld)
        ++off;
    uneven[off] += 0.5;
    EXPECT_EQ(leastSquaresMesh(mesh, uneven, kHeld, mirror), leastSquaresMesh(mesh, uneven, kHeld));
}

}  // namespace
}  // namespace rigmesh
