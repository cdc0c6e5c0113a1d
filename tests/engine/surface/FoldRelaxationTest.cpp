// surface/FoldRelaxation: a fold is spread over its neighbourhood, the
// outline and the mirror symmetry stay exact, and nothing far from a fold
// moves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SurfaceTestSupport.h"
#include "mesh/SurfaceQuality.h"
#include "surface/FoldRelaxation.h"

namespace rigmesh {
namespace {

// The interior vertex nearest the middle of the tube's upper side, pushed
// out by one edge length along z with its mirror image: a sharp spike.
int pushSpike(SketchSurface& surface, double height) {
    auto& p = surface.mesh.vertices;
    Eigen::AlignedBox3d box;
    for (const Vec3& v : p)
        box.extend(v);
    const Vec3 top(box.center().x(), box.center().y(), box.max().z());
    int spike = -1;
    for (int v = 0; v < static_cast<int>(p.size()); ++v)
        if (!surface.origins[v].onOutline && p[v].z() > 0 &&
            (spike < 0 || (p[v] - top).norm() < (p[spike] - top).norm()))
            spike = v;
    p[spike].z() += height;
    const int m = surface.mirror[spike];
    p[m] = Vec3(p[spike].x(), p[spike].y(), -p[spike].z());
    return spike;
}

double edgeLength(const TriMesh& mesh) {
    const auto& f = mesh.faces.front();
    return (mesh.vertices[f[0]] - mesh.vertices[f[1]]).norm();
}

TEST(FoldRelaxation, ASpikeIsSpreadWhileTheOutlineAndTheMirrorStayExact) {
    SketchSurface surface = surfacetest::sharedResult("tube").surface;
    const double h = edgeLength(surface.mesh);
    const int spike = pushSpike(surface, 1.5 * h);
    const SketchSurface before = surface;
    ASSERT_GT(normalAngles(surface.mesh).max, 60.0);

    EXPECT_GT(relaxFolds(surface), 0);

    const NormalAngles after = normalAngles(surface.mesh);
    EXPECT_LE(after.max, 35.0);
    const auto& p = surface.mesh.vertices;
    for (int v = 0; v < static_cast<int>(p.size()); ++v) {
        if (before.origins[v].onOutline) {
            EXPECT_EQ(p[v], before.mesh.vertices[v]) << "outline vertex " << v << " moved";
        }
        const Vec3& m = p[surface.mirror[v]];
        EXPECT_EQ(m, Vec3(p[v].x(), p[v].y(), -p[v].z())) << "vertex " << v;
        // Only the fold's neighbourhood moves: a few edges around the spike.
        if ((before.mesh.vertices[v] - before.mesh.vertices[spike]).norm() > 8 * h &&
            (before.mesh.vertices[v] - before.mesh.vertices[surface.mirror[spike]]).norm() >
                8 * h) {
            EXPECT_EQ(p[v], before.mesh.vertices[v]) << "vertex " << v << " far from the fold";
        }
    }
}

TEST(FoldRelaxation, ASurfaceWithoutFoldsIsLeftAlone) {
    // The tube's faces meet at most 14 degrees apart: no fold to relax.
    SketchSurface surface = surfacetest::sharedResult("tube").surface;
    ASSERT_LT(normalAngles(surface.mesh).max, 20.0);
    const std::vector<Vec3> before = surface.mesh.vertices;
    EXPECT_EQ(relaxFolds(surface), 0);
    EXPECT_EQ(surface.mesh.vertices, before);
}

}  // namespace
}  // namespace rigmesh
