// surface/FoldRelaxation: a fold is spread over its neighbourhood, the
// outline and the mirror symmetry stay exact, and nothing far from a fold
// moves; a fold at the outline itself (a notch in the silhouette) is spread
// by moving the outline vertices there within the sketch plane, only when
// allowed and only within the allowed shift.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "SurfaceTestSupport.h"
#include "mesh/SurfaceQuality.h"
#include "surface/FoldRelaxation.h"

namespace rigmesh {
namespace {

// The bounding box of the surface's vertices.
Eigen::AlignedBox3d boxOf(const SketchSurface& surface) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : surface.mesh.vertices)
        box.extend(v);
    return box;
}

// The vertex on (or off) the outline nearest `target`.
int nearestVertex(const SketchSurface& surface, const Vec3& target, bool onOutline) {
    const auto& p = surface.mesh.vertices;
    int nearest = -1;
    for (int v = 0; v < static_cast<int>(p.size()); ++v)
        if (surface.origins[v].onOutline == onOutline && p[v].z() >= 0 &&
            (nearest < 0 || (p[v] - target).norm() < (p[nearest] - target).norm()))
            nearest = v;
    return nearest;
}

// The interior vertex nearest the middle of the tube's upper side, pushed
// out by one edge length along z with its mirror image: a sharp spike.
int pushSpike(SketchSurface& surface, double height) {
    auto& p = surface.mesh.vertices;
    const Eigen::AlignedBox3d box = boxOf(surface);
    const int spike =
        nearestVertex(surface, Vec3(box.center().x(), box.center().y(), box.max().z()), false);
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

// The outline vertex nearest the middle of the tube's side, pulled in along
// the sketch plane towards the axis by `depth`: a notch in the silhouette,
// whose faces fold at that vertex.
int pullNotch(SketchSurface& surface, double depth) {
    auto& p = surface.mesh.vertices;
    const Vec3 centre = boxOf(surface).center();
    const int notch = nearestVertex(surface, centre, true);
    Vec3 inward = centre - p[notch];
    inward.z() = 0;
    p[notch] += depth * inward.normalized();
    return notch;
}

TEST(FoldRelaxation, AFoldAtTheOutlineMovesTheOutlineThereWithinTheShiftInThePlane) {
    SketchSurface surface = surfacetest::sharedResult("tube").surface;
    const double h = edgeLength(surface.mesh);
    const int notch = pullNotch(surface, 0.8 * h);
    const SketchSurface notched = surface;
    ASSERT_GT(normalAngles(surface.mesh).max, 45.0);

    // Held, the outline keeps the fold however the rest moves.
    SketchSurface held = notched;
    relaxFolds(held);
    EXPECT_GT(normalAngles(held.mesh).max, 35.0);

    FoldRelaxationOptions options;
    options.outlineShift = 0.5 * h;
    EXPECT_GT(relaxFolds(surface, options), 0);
    EXPECT_LE(normalAngles(surface.mesh).max, 35.0);
    const auto& p = surface.mesh.vertices;
    int outlineMoved = 0;
    for (int v = 0; v < static_cast<int>(p.size()); ++v) {
        const Vec3& m = p[surface.mirror[v]];
        EXPECT_EQ(m, Vec3(p[v].x(), p[v].y(), -p[v].z())) << "vertex " << v;
        if (!notched.origins[v].onOutline)
            continue;
        EXPECT_EQ(p[v].z(), 0.0) << "outline vertex " << v << " left the sketch plane";
        EXPECT_LE((p[v] - notched.mesh.vertices[v]).norm(), options.outlineShift + 1e-12);
        if (p[v] != notched.mesh.vertices[v]) {
            ++outlineMoved;
            // Only the outline at the fold: within a couple of edges of the notch.
            EXPECT_LT((notched.mesh.vertices[v] - notched.mesh.vertices[notch]).norm(), 2.5 * h)
                << "outline vertex " << v << " far from the fold moved";
        }
    }
    EXPECT_GT(outlineMoved, 0);
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
