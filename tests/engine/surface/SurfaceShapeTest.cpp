// The surface has the sketch's silhouette and real depth: its xy projection
// matches the cleaned outline and it bulges in front of and behind the plane.
#include <gtest/gtest.h>

#include <string>

#include "SilhouetteRaster.h"
#include "SurfaceTestSupport.h"

namespace rigmesh {
namespace {

constexpr int kRasterResolution = 256;
constexpr double kMinSilhouetteIoU = 0.9;
constexpr double kMinDepthRatio = 0.1;  // of the smaller of the outline's x and y extents

class SketchSurfaceShape : public ::testing::TestWithParam<std::string> {
  protected:
    const SketchToSurfaceResult& result() const { return surfacetest::sharedResult(GetParam()); }
};

TEST_P(SketchSurfaceShape, SilhouetteMatchesCleanedOutline) {
    const auto& outline = result().polygon.points;
    const TriMesh& mesh = result().surface.mesh;
    Eigen::AlignedBox2d box;
    for (const Vec2& p : outline)
        box.extend(p);
    for (const Vec3& v : mesh.vertices)
        box.extend(Vec2(v.head<2>()));

    surfacetest::SilhouetteGrid sketch(box, kRasterResolution), surface(box, kRasterResolution);
    sketch.fillPolygon(outline);
    surface.fillProjection(mesh);
    const double iou = surfacetest::SilhouetteGrid::intersectionOverUnion(sketch, surface);
    EXPECT_GE(iou, kMinSilhouetteIoU)
        << "sketch pixels " << sketch.filledCount() << ", surface pixels " << surface.filledCount();
    RecordProperty("silhouette_iou", std::to_string(iou));
}

TEST_P(SketchSurfaceShape, BulgesInFrontOfAndBehindSketchPlane) {
    const auto box = surfacetest::boundingBox(result().surface.mesh);
    const double smallerExtent = std::min(box.sizes().x(), box.sizes().y());
    EXPECT_GT(box.max().z(), kMinDepthRatio * smallerExtent);
    EXPECT_LT(box.min().z(), -kMinDepthRatio * smallerExtent);
}

INSTANTIATE_TEST_SUITE_P(SharedSketches, SketchSurfaceShape,
                         ::testing::ValuesIn(testsupport::sharedSketchNames(false)),
                         testsupport::sketchTestName);

}  // namespace
}  // namespace rigmesh
