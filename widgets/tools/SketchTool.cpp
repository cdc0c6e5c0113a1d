#include "tools/SketchTool.h"

#include <QLineF>

#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {
namespace {

// A press and release this close on screen is a click, not a stroke.
constexpr double kClickPixels = 4.0;
// A stroke is judged by its size on screen, not by how many mouse events a
// fast or slow hand produced.
constexpr double kMinimumExtentPixels = 12.0;
constexpr double kMinimumLengthPixels = 40.0;
// Fast strokes arrive as few, far-apart events: the polyline is filled in to
// at most this spacing before it becomes a sketch.
constexpr double kMaxSpacingPixels = 3.0;

double pathLength(const std::vector<QPointF>& pixels) {
    double length = 0.0;
    for (std::size_t i = 1; i < pixels.size(); ++i)
        length += QLineF(pixels[i - 1], pixels[i]).length();
    return length;
}

std::vector<QPointF> filledIn(const std::vector<QPointF>& pixels) {
    std::vector<QPointF> dense;
    for (std::size_t i = 0; i + 1 < pixels.size(); ++i) {
        const QPointF& a = pixels[i];
        const QPointF& b = pixels[i + 1];
        dense.push_back(a);
        const int steps = static_cast<int>(QLineF(a, b).length() / kMaxSpacingPixels);
        for (int k = 1; k < steps; ++k)
            dense.push_back(a + (b - a) * (double(k) / steps));
    }
    dense.push_back(pixels.back());
    return dense;
}

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
    const double length = pathLength(pixels_);
    if (length < kClickPixels) {
        pixels_.clear();  // a click: nothing to sketch, nothing to say
        return;
    }
    QRectF extent(pixels_.front(), QSizeF(0, 0));
    for (const QPointF& p : pixels_)
        extent |= QRectF(p, QSizeF(0.001, 0.001));
    if (length < kMinimumLengthPixels ||
        std::max(extent.width(), extent.height()) < kMinimumExtentPixels) {
        pixels_.clear();
        emit status(tr("That stroke is too short: drag to draw a closed outline"), 5000);
        return;
    }
    pixels_ = filledIn(pixels_);
    // Into the sketch plane's own 2D frame (x = camera right, y = camera up).
    const model::Placement plane = viewport.sketchPlacement();
    const Eigen::Quaterniond toPlane = plane.rotation.conjugate();
    std::vector<Vec2> stroke;
    stroke.reserve(pixels_.size());
    for (const QPointF& pixel : pixels_) {
        const QVector3D world = viewport.sketchPlanePoint(pixel);
        const Vec3 local = toPlane * (toEigen(world) - plane.translation);
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
