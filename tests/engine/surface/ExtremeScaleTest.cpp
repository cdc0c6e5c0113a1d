// Sketches far from the origin or at extreme sizes: the pipeline works in the
// stroke's local frame, so it builds the same surface (moved) or refuses
// with a message when double precision cannot place the vertices. Never a
// hang, never a non-finite vertex, never a degenerate face.
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "SurfaceTestSupport.h"
#include "pipeline/SurfaceLimits.h"

namespace rigmesh {
namespace {

std::vector<Vec2> transformed(const std::string& sketch, double scale, double shift) {
    std::vector<Vec2> stroke = testsupport::sharedSketchPoints(sketch);
    for (Vec2& p : stroke)
        p = scale * p + Vec2(shift, shift);
    return stroke;
}

std::string errorOf(const std::vector<Vec2>& stroke, const SketchToSurfaceOptions& options = {}) {
    try {
        sketchToSurface(stroke, options);
    } catch (const Error& error) {
        return error.what();
    }
    return "";
}

void expectValidSurface(const SketchToSurfaceResult& result, const std::string& what) {
    for (const Vec3& v : result.surface.mesh.vertices)
        ASSERT_TRUE(v.allFinite()) << what;
    const MeshReport report = analyseMesh(result.surface.mesh, false);
    EXPECT_TRUE(report.isWatertightGenus0()) << what;
    EXPECT_EQ(report.degenerateFaces, 0) << what;
}

TEST(ExtremeScale, SketchesTranslatedFarStillBuildTheSameSurfaceMoved) {
    constexpr double kShift = 1e6;
    for (const std::string& sketch : testsupport::sharedSketchNames(false)) {
        const TriMesh& reference = surfacetest::sharedResult(sketch).surface.mesh;
        const SketchToSurfaceResult moved = sketchToSurface(transformed(sketch, 1.0, kShift));
        expectValidSurface(moved, sketch);
        ASSERT_EQ(moved.surface.mesh.vertexCount(), reference.vertexCount()) << sketch;
        // The only loss is the rounding of coordinates near 1e6.
        const double tolerance = 1e-6 * surfacetest::boundingBox(reference).diagonal().norm();
        double worst = 0;
        for (int v = 0; v < reference.vertexCount(); ++v)
            worst = std::max(worst, (moved.surface.mesh.vertices[v] - Vec3(kShift, kShift, 0) -
                                     reference.vertices[v])
                                        .norm());
        EXPECT_LE(worst, tolerance) << sketch;
    }
}

TEST(ExtremeScale, SketchTooFarForItsSizeIsRefusedWithAMessage) {
    for (const std::string& sketch : testsupport::sharedSketchNames(false)) {
        const std::string message = errorOf(transformed(sketch, 1.0, 1e15));
        EXPECT_NE(message.find("too far from the origin"), std::string::npos)
            << sketch << ": " << message;
    }
}

TEST(ExtremeScale, TinyAndHugeSketchesBuildWithoutDegenerateFaces) {
    for (const std::string& sketch : testsupport::sharedSketchNames(false))
        for (double scale : {1e-30, 1e-6, 1e6, 1e20})
            expectValidSurface(sketchToSurface(transformed(sketch, scale, 0.0)),
                               sketch + " scaled by " + std::to_string(scale));
}

TEST(ExtremeScale, SizesBeyondTheSupportedRangeAreRefused) {
    EXPECT_NE(errorOf(transformed("tube", 1e40, 0.0)).find("sizes from"), std::string::npos);
    EXPECT_NE(errorOf(transformed("tube", 1e-60, 0.0)).find("sizes from"), std::string::npos);
    EXPECT_NE(errorOf(transformed("tube", 1e28, 1e40)).find("too far"), std::string::npos);
    // A box wider than the largest double: its size overflows, still a message.
    const std::vector<Vec2> widest{{-1.7e308, 0}, {1.7e308, 0}, {1e308, 1e308}, {0, 1e308}};
    EXPECT_NE(errorOf(widest).find("sizes from"), std::string::npos) << errorOf(widest);
}

TEST(EdgeLengthBudget, EdgeLengthGivingTooManyVerticesIsRefusedWithTheAllowedRange) {
    for (double scale : {1e-6, 1.0, 1e6}) {
        SketchToSurfaceOptions options;
        options.surface.targetEdgeLength = 1e-5 * scale;
        const std::string message = errorOf(transformed("biped", scale, 0.0), options);
        EXPECT_NE(message.find("too small"), std::string::npos) << message;
        EXPECT_NE(message.find("at least"), std::string::npos) << message;
    }
}

TEST(EdgeLengthBudget, BudgetIsRelativeToTheOutlineSize) {
    // A quarter of the automatic edge length is fine at every scale.
    for (double scale : {1e-6, 1.0, 1e6}) {
        const std::vector<Vec2> stroke = transformed("tube", scale, 0.0);
        SketchToSurfaceOptions options;
        options.surface.targetEdgeLength = 0.25 * sketchToSurface(stroke).targetEdgeLength;
        expectValidSurface(sketchToSurface(stroke, options), "tube quarter edge");
    }
}

TEST(EdgeLengthBudget, NonFiniteOrNegativeEdgeLengthIsRefused) {
    for (double length : {-1.0, std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN()}) {
        SketchToSurfaceOptions options;
        options.surface.targetEdgeLength = length;
        EXPECT_NE(errorOf(testsupport::sharedSketchPoints("tube"), options).find("edge length"),
                  std::string::npos)
            << length;
    }
}

TEST(BuiltMeshCheck, NonFiniteVertexOrDegenerateFaceIsRefused) {
    TriMesh mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
    mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    EXPECT_NO_THROW(checkBuiltMesh(mesh));

    TriMesh withNan = mesh;
    withNan.vertices[3].z() = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THROW(checkBuiltMesh(withNan), Error);

    TriMesh collapsed = mesh;
    collapsed.vertices[3] = Vec3(0.5, 0.5, 0);  // on the plane of face 0's edge
    collapsed.faces.push_back({1, 1, 2});
    EXPECT_THROW(checkBuiltMesh(collapsed), Error);
}

}  // namespace
}  // namespace rigmesh
