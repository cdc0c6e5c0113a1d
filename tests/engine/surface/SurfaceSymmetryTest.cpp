// The surface is mirror-symmetric through the sketch plane (paper 2.2): each
// vertex's mirror has the same x, y and the opposite z, and the outline lies
// in the plane.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <set>
#include <string>

#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

constexpr double kMirrorTolerance = 1e-12;  // relative to the bounding-box diagonal

class SketchSurfaceSymmetry : public ::testing::TestWithParam<std::string> {
  protected:
    const SketchSurface& surface() const { return surfacetest::sharedResult(GetParam()).surface; }
};

TEST_P(SketchSurfaceSymmetry, MirrorVertexIsReflectionThroughSketchPlane) {
    const SketchSurface& s = surface();
    const int n = s.mesh.vertexCount();
    ASSERT_EQ(static_cast<int>(s.mirror.size()), n);
    const double tolerance = kMirrorTolerance * surfacetest::boundingBox(s.mesh).diagonal().norm();
    int wrong = 0;
    for (int v = 0; v < n; ++v) {
        const int m = s.mirror[v];
        ASSERT_GE(m, 0);
        ASSERT_LT(m, n);
        EXPECT_EQ(s.mirror[m], v) << "mirror is not an involution at " << v;
        const Vec3& p = s.mesh.vertices[v];
        const Vec3& q = s.mesh.vertices[m];
        const double error = (Vec3(p.x(), p.y(), -p.z()) - q).norm();
        if (error > tolerance && ++wrong <= 5)
            ADD_FAILURE() << "vertex " << v << " and mirror " << m << " differ by " << error;
    }
    EXPECT_EQ(wrong, 0);
}

TEST_P(SketchSurfaceSymmetry, OutlineVerticesLieInSketchPlane) {
    const SketchSurface& s = surface();
    ASSERT_EQ(s.origins.size(), s.mesh.vertices.size());
    int outline = 0;
    for (std::size_t v = 0; v < s.origins.size(); ++v) {
        if (!s.origins[v].onOutline)
            continue;
        ++outline;
        EXPECT_EQ(s.mesh.vertices[v].z(), 0.0) << "outline vertex " << v;
        EXPECT_EQ(s.mirror[v], static_cast<int>(v)) << "outline vertex " << v;
    }
    EXPECT_GE(outline, 3);
}

TEST_P(SketchSurfaceSymmetry, MirrorMapsFacesToFaces) {
    const TriMesh& mesh = surface().mesh;
    const auto& mirror = surface().mirror;
    std::set<std::array<int, 3>> faces;
    const auto canonical = [](std::array<int, 3> f) {
        std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
        return f;
    };
    for (const auto& f : mesh.faces)
        faces.insert(canonical(f));
    for (const auto& f : mesh.faces) {
        // Reflection reverses orientation.
        const std::array<int, 3> image{mirror[f[0]], mirror[f[2]], mirror[f[1]]};
        EXPECT_TRUE(faces.count(canonical(image)))
            << "face " << f[0] << " " << f[1] << " " << f[2] << " has no mirror image";
    }
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SketchSurfaceSymmetry,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
