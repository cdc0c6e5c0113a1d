// The surface figures (mesh/SurfaceQuality.h) as guards, on every shared sketch (and the quadruped
// of tests/data/sketches and the blob with a bump) at the default edge length and on random
// outlines with many branches and thin parts: neighbouring face normals at most 20 degrees apart at
// the 99th percentile and 35 on every edge, a front view whose silhouette covers the cleaned
// outline (IoU >= 0.95), at least 12 vertices around every body cross section, and a vertex count
// that follows the area over the local edge length squared.
//
// One outline does not meet every target yet; it is listed in
// kOpenShortfalls with the figure measured when this test was written, which
// it must not exceed (see the crease report in
// SurfaceCreaseReportTest for where the angles sit).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <numbers>
#include <random>
#include <string>

#include "SurfaceTestSupport.h"
#include "mesh/MeshChecks.h"
#include "mesh/SurfaceQuality.h"

namespace rigmesh {
namespace {

constexpr double kP99Limit = 20.0;
constexpr double kMaxLimit = 35.0;
constexpr double kIoULimit = 0.95;
constexpr int kRingLimit = 12;

// Measured 2026-11-25. caterpillar: its seven narrow bumps (0.36 wide on a
// body 1.4 across) stand too close together for a body piece between their
// patches (axis/Decomposition.cpp: bumpRun), so they are left to the body's
// sections and shaved (IoU 0.945); as one-sleeve patches they came out as
// horns with folds of up to 122 degrees around them, as one patch along the
// body with folds of 47. (The biped's crotch, 78 degrees on a 90-degree concave
// corner, and the quadruped's, 55, meet every target since the surface is
// built on the outline with concave corners rounded, each point moving at
// most one spacing: 32.0 and 30.7.)
struct Shortfall {
    double max = kMaxLimit;
    double p99 = kP99Limit;
    double iou = kIoULimit;
};
const std::map<std::string, Shortfall> kOpenShortfalls{
    {"caterpillar", {kMaxLimit, kP99Limit, 0.94}},
};

std::vector<std::string> sketchNames() {
    std::vector<std::string> names = testsupport::sharedSketchNames(false);
    names.push_back("quadruped");
    names.push_back("blob_bump");
    names.push_back("caterpillar");
    return names;
}

std::vector<Vec2> sketchPoints(const std::string& name) {
    if (name == "blob_bump")
        return testsupport::blobWithBump();
    if (name == "caterpillar")
        return testsupport::bumpyCaterpillar();
    if (name == "quadruped")
        return readSketchFile(std::string(RIGMESH_TEST_DATA) + "/sketches/quadruped.json").points;
    return testsupport::sharedSketchPoints(name);
}

// Vertices around each body cross section, smallest (surfacetest::ringSizes).
int smallestRing(const SketchToSurfaceResult& result) {
    const std::vector<int> sizes = surfacetest::ringSizes(result);
    return sizes.empty() ? std::numeric_limits<int>::max()
                         : *std::min_element(sizes.begin(), sizes.end());
}

// The surface area each cross section's strip stands for, over its local
// edge length squared, summed: the vertex count the local edge lengths ask
// for, up to the constant of a regular triangulation (area / (sqrt(3)/2 h^2)
// vertices for an equilateral one).
double expectedVertices(const SketchToSurfaceResult& result) {
    const TriMesh& mesh = result.surface.mesh;
    double sum = 0;
    for (const auto& f : mesh.faces) {
        double spacing = result.targetEdgeLength;
        for (int v : f) {
            const VertexOrigin& o = result.surface.origins[v];
            if (o.kind == RegionKind::Cylindrical && o.section >= 0) {
                const double s = result.cylinders[o.region].sections[o.section].spacing;
                if (s > 0)
                    spacing = std::min(spacing, s);
            }
        }
        const double area = 0.5 * (mesh.vertices[f[1]] - mesh.vertices[f[0]])
                                      .cross(mesh.vertices[f[2]] - mesh.vertices[f[0]])
                                      .norm();
        sum += area / (std::sqrt(3.0) / 2.0 * spacing * spacing);
    }
    return sum;
}

struct Figures {
    NormalAngles angles;
    double iou = 0;
    int ring = 0;
    int vertices = 0;
    double density = 0;       // vertices / (area / target edge length^2)
    double localDensity = 0;  // vertices / expectedVertices
};

Figures measure(const SketchToSurfaceResult& result) {
    Figures f;
    f.angles = normalAngles(result.surface.mesh);
    f.iou = silhouetteIoU(result.surface.mesh, result.polygon.points);
    f.ring = smallestRing(result);
    f.vertices = result.surface.mesh.vertexCount();
    const double h = result.targetEdgeLength;
    f.density = f.vertices / (surfaceArea(result.surface.mesh) / (h * h));
    f.localDensity = f.vertices / expectedVertices(result);
    return f;
}

class SurfaceFigures : public testing::TestWithParam<std::string> {};

TEST_P(SurfaceFigures, SmoothRoundAndTrueToTheOutline) {
    const SketchToSurfaceResult result = sketchToSurface(sketchPoints(GetParam()));
    const Figures f = measure(result);
    std::printf(
        "%-11s p99 %5.1f max %5.1f IoU %.4f ring %2d vertices %5d "
        "(x h^2/area %.2f, / local %.2f)\n",
        GetParam().c_str(), f.angles.p99, f.angles.max, f.iou, f.ring, f.vertices, f.density,
        f.localDensity);
    const auto open = kOpenShortfalls.find(GetParam());
    const Shortfall limits = open == kOpenShortfalls.end() ? Shortfall{} : open->second;
    EXPECT_LE(f.angles.p99, limits.p99);
    EXPECT_LE(f.angles.max, limits.max);
    EXPECT_GE(f.iou, limits.iou);
    if (!result.cylinders.empty()) {
        EXPECT_GE(f.ring, kRingLimit);
    }
    // A regular triangulation at the local edge lengths has one vertex per
    // sqrt(3)/2 h^2 of area; strips and patches are close to it.
    EXPECT_GT(f.localDensity, 0.6);
    EXPECT_LT(f.localDensity, 1.6);
}

INSTANTIATE_TEST_SUITE_P(Sketches, SurfaceFigures, testing::ValuesIn(sketchNames()),
                         testsupport::sketchTestName);

// Halving the edge length of a part wide everywhere (no thin part takes the
// radius rule) gives four times the vertices: the count follows area / h^2.
TEST(SurfaceFiguresScaling, AWideBlobHasFourTimesTheVerticesAtHalfTheEdgeLength) {
    std::vector<Vec2> blob;
    for (int i = 0; i < 256; ++i) {
        const double t = 2 * std::numbers::pi * i / 256;
        blob.emplace_back(2.0 * std::cos(t), 1.4 * std::sin(t));
    }
    SketchToSurfaceOptions coarse, fine;
    coarse.surface.targetEdgeLength = 0.2;
    fine.surface.targetEdgeLength = 0.1;
    const int a = sketchToSurface(blob, coarse).surface.mesh.vertexCount();
    const int b = sketchToSurface(blob, fine).surface.mesh.vertexCount();
    EXPECT_NEAR(double(b) / a, 4.0, 0.6) << a << " -> " << b;
}

// A blob with several arms of random length, width and direction, some thin
// (half-widths down to a third of the default edge length), as a CCW outline.
std::vector<Vec2> branchyOutline(std::mt19937& random) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const int arms = 3 + static_cast<int>(5 * unit(random));
    struct Arm {
        double angle, length, width;
    };
    std::vector<Arm> list;
    for (int k = 0; k < arms; ++k)
        list.push_back({2 * std::numbers::pi * (k + 0.3 * unit(random)) / arms,
                        0.8 + 1.5 * unit(random), 0.04 + 0.12 * unit(random)});
    std::vector<Vec2> points;
    constexpr int kCount = 720;
    for (int i = 0; i < kCount; ++i) {
        const double t = 2 * std::numbers::pi * i / kCount;
        double r = 0.8;
        for (const Arm& arm : list) {
            // Angular distance to the arm's direction; the arm is a ridge of
            // about constant width `width` (its angular half-width shrinks
            // with the radius reached).
            const double d = std::remainder(t - arm.angle, 2 * std::numbers::pi);
            const double reach = 0.8 + arm.length;
            const double halfAngle = arm.width / reach;
            const double x = d / halfAngle;
            if (std::abs(x) < 3.0)
                r = std::max(r, 0.8 + arm.length * std::exp(-std::pow(x, 4) / 4.0));
        }
        points.push_back(r * Vec2(std::cos(t), std::sin(t)));
    }
    return points;
}

// Every figure holds on these outlines too: the central blob's arcs between
// arms, pruned bumps off the sleeves crossing it, are connecting regions
// (IoU 0.73 -> 0.95); thin arms get outline points at a third of their width
// (0.97 and up); caps begin at chords square to their limbs, their outline
// paths keep no corner sharper than 1.5 local edge lengths, a needle's tip
// is sliced finer, and the sections next to a fixed end chord follow the
// outline (max 77 -> 43.5 -> 33.4 degrees at worst).
TEST(SurfaceFiguresRandom, BranchyOutlinesMeetEveryFigure) {
    std::mt19937 random(1012);
    constexpr int kCases = 10;
    for (int c = 0; c < kCases; ++c) {
        SCOPED_TRACE("random outline " + std::to_string(c));
        const std::vector<Vec2> outline = branchyOutline(random);
        const SketchToSurfaceResult result = sketchToSurface(outline);
        const Figures f = measure(result);
        std::printf(
            "random %2d: %zu cylinders, p99 %5.1f max %5.1f IoU %.4f ring %2d "
            "vertices %5d (/ local %.2f)\n",
            c, result.cylinders.size(), f.angles.p99, f.angles.max, f.iou, f.ring, f.vertices,
            f.localDensity);
        EXPECT_LE(f.angles.p99, kP99Limit);
        EXPECT_LE(f.angles.max, kMaxLimit);
        EXPECT_GE(f.iou, kIoULimit);
        EXPECT_GE(f.ring, kRingLimit);
    }
}

}  // namespace
}  // namespace rigmesh
