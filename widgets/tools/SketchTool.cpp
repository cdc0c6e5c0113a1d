#include "tools/SketchTool.h"

#include "viewport/Viewport.h"

namespace rigmesh::widgets {
namespace {

constexpr int kMinimumPoints = 8;
constexpr double kMinimumExtentPixels = 12.0;

}  // namespace

QString SketchTool::hint() const {
    return tr(
        "Sketch: drag with the left button to draw a closed silhouette; release to inflate it into "
        "a rigged part");
}

void SketchTool::press(Viewport& viewport, QMouseEvent* event) {
    drawing_ = true;
    pixels_ = {event->position()};
    viewport.setStrokeOverlay({viewport.sketchPlanePoint(event->position())});
}

void SketchTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!drawing_)
        return;
    pixels_.push_back(event->position());
    std::vector<QVector3D> overlay;
    overlay.reserve(pixels_.size());
    for (const QPointF& p : pixels_)
        overlay.push_back(viewport.sketchPlanePoint(p));
    viewport.setStrokeOverlay(std::move(overlay));
}

void SketchTool::release(Viewport& viewport, QMouseEvent* event) {
    if (!drawing_)
        return;
    drawing_ = false;
    pixels_.push_back(event->position());
    viewport.setStrokeOverlay({});
    QRectF extent(pixels_.front(), QSizeF(0, 0));
    for (const QPointF& p : pixels_)
        extent |= QRectF(p, QSizeF(0.001, 0.001));
    if (static_cast<int>(pixels_.size()) < kMinimumPoints ||
        std::max(extent.width(), extent.height()) < kMinimumExtentPixels) {
        emit hintMessage(tr("That stroke is too short: drag to draw a closed outline"));
        return;
    }
    // Into the sketch plane's own 2D frame (x = camera right, y = camera up).
    const model::Placement plane = viewport.sketchPlacement();
    const Eigen::Quaterniond toPlane = plane.rotation.conjugate();
    std::vector<Vec2> stroke;
    stroke.reserve(pixels_.size());
    for (const QPointF& pixel : pixels_) {
        const QVector3D world = viewport.sketchPlanePoint(pixel);
        const Vec3 local = toPlane * (Vec3(world.x(), world.y(), world.z()) - plane.translation);
        stroke.emplace_back(local.x(), local.y());
    }
    pixels_.clear();
    emit strokeFinished(stroke, plane);
}

void SketchTool::cancel(Viewport& viewport) {
    drawing_ = false;
    pixels_.clear();
    viewport.setStrokeOverlay({});
}

}  // namespace rigmesh::widgets
