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

// A stroke long and wide enough on screen to be sketched (else a click or
// a flick, refused on release).
bool bigEnough(const std::vector<QPointF>& pixels) {
    QRectF extent(pixels.front(), QSizeF(0, 0));
    for (const QPointF& p : pixels)
        extent |= QRectF(p, QSizeF(0.001, 0.001));
    return pathLength(pixels) >= kMinimumLengthPixels &&
           std::max(extent.width(), extent.height()) >= kMinimumExtentPixels;
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
    plane_ = viewport.sketchPlacement();
    pixels_ = {event->position()};
    viewport.setStrokeOverlay({onPlane(viewport, event->position())});
}

void SketchTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!drawing_)
        return;
    pixels_.push_back(event->position());
    std::vector<QVector3D> overlay;
    overlay.reserve(pixels_.size());
    for (const QPointF& p : pixels_)
        overlay.push_back(onPlane(viewport, p));
    viewport.setStrokeOverlay(std::move(overlay));
    if (bigEnough(pixels_))
        emit strokeChanged(planeStroke(viewport), plane_);
}

void SketchTool::release(Viewport& viewport, QMouseEvent* event) {
    if (!drawing_)
        return;
    drawing_ = false;
    // A release where the last move was adds nothing: the stroke is the one
    // the last move previewed.
    if (event->position() != pixels_.back())
        pixels_.push_back(event->position());
    viewport.setStrokeOverlay({});
    if (pathLength(pixels_) < kClickPixels) {
        pixels_.clear();  // a click: nothing to sketch, nothing to say
        emit strokeAbandoned();
        return;
    }
    if (!bigEnough(pixels_)) {
        pixels_.clear();
        emit strokeAbandoned();
        emit status(tr("That stroke is too short: drag to draw a closed outline"), 5000);
        return;
    }
    const std::vector<Vec2> stroke = planeStroke(viewport);
    pixels_.clear();
    emit strokeFinished(stroke, plane_);
}

QVector3D SketchTool::onPlane(const Viewport& viewport, const QPointF& pixel) const {
    return viewport.viewPlanePoint(pixel, toQt(plane_.translation));
}

std::vector<Vec2> SketchTool::planeStroke(const Viewport& viewport) const {
    // Into the sketch plane's own 2D frame (x = camera right, y = camera up).
    const Eigen::Quaterniond toPlane = plane_.rotation.conjugate();
    std::vector<Vec2> stroke;
    const std::vector<QPointF> dense = filledIn(pixels_);
    stroke.reserve(dense.size());
    for (const QPointF& pixel : dense) {
        const Vec3 local = toPlane * (toEigen(onPlane(viewport, pixel)) - plane_.translation);
        stroke.emplace_back(local.x(), local.y());
    }
    return stroke;
}

void SketchTool::cancel(Viewport& viewport) {
    const bool wasDrawing = drawing_;
    drawing_ = false;
    pixels_.clear();
    viewport.setStrokeOverlay({});
    if (wasDrawing)
        emit strokeAbandoned();
}

}  // namespace rigmesh::widgets
