#include "tools/CutTool.h"

#include <Eigen/Geometry>
#include <map>

#include "UserAction.h"
#include "base/Error.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/CutPartCommand.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// A stroke shorter than this on screen is a click.
constexpr double kMinimumPixels = 20.0;
// The stroke keeps a point every this many pixels; the crossing test looks
// at a few points along each of its segments.
constexpr double kSpacingPixels = 8.0;
constexpr int kSamplesPerSegment = 4;

}  // namespace

QString CutTool::hint() const {
    return tr(
        "Cut: drag a line across a part, from outside it to outside it; release cuts it in two "
        "with a smooth face, Shift + release with a flat one; Esc cancels");
}

void CutTool::press(Viewport& viewport, QMouseEvent* event) {
    pixels_ = {event->position()};
    planePoint_ = viewport.sketchPlanePoint(event->position());
    overlay_ = {planePoint_};
    viewport.setStrokeOverlay(overlay_);
}

void CutTool::move(Viewport& viewport, QMouseEvent* event) {
    if (pixels_.empty() || !(event->buttons() & Qt::LeftButton))
        return;
    pixels_.push_back(event->position());
    overlay_.push_back(viewport.viewPlanePoint(event->position(), planePoint_));
    viewport.setStrokeOverlay(overlay_);
}

void CutTool::release(Viewport& viewport, QMouseEvent* event) {
    if (pixels_.empty())
        return;
    pixels_.push_back(event->position());
    // Every few pixels along the drag: the stroke the cut sweeps.
    std::vector<QPointF> stroke{pixels_.front()};
    for (const QPointF& p : pixels_)
        if (QLineF(stroke.back(), p).length() >= kSpacingPixels)
            stroke.push_back(p);
    if (stroke.back() != pixels_.back())
        stroke.push_back(pixels_.back());
    pixels_.clear();
    overlay_.clear();
    viewport.setStrokeOverlay({});
    const QPointF a = stroke.front();
    const QPointF b = stroke.back();
    if (QLineF(a, b).length() < kMinimumPixels)
        return;  // a click
    // The part the stroke crosses most, which neither end may touch (paper
    // 3.1: the stroke must cross the silhouette completely).
    std::map<model::PartId, int> crossed;
    for (std::size_t i = 0; i + 1 < stroke.size(); ++i)
        for (int k = 0; k < kSamplesPerSegment; ++k)
            if (auto part =
                    viewport.partAt(stroke[i] + (stroke[i + 1] - stroke[i]) *
                                                    (static_cast<double>(k) / kSamplesPerSegment)))
                ++crossed[*part];
    if (crossed.empty()) {
        emit status(tr("Nothing cut: the line does not cross a part"));
        return;
    }
    const model::PartId part =
        std::max_element(crossed.begin(), crossed.end(), [](const auto& x, const auto& y) {
            return x.second < y.second;
        })->first;
    if (viewport.partAt(a) == part || viewport.partAt(b) == part) {
        emit status(
            tr("Nothing cut: draw the line across the whole part, from outside it to outside it"));
        return;
    }
    model::Document& document = *viewport.document();
    const model::PartNode& node = document.part(part);
    const Eigen::AlignedBox3d box = model::worldBounds(node);
    // The stroke on the view plane through the part's centre, in that
    // plane's (right, up) coordinates: the recipe's form.
    const QVector3D centre = toQt(box.center());
    model::CutSpec spec;
    spec.viewDirection = toEigen(viewport.camera().forward()).normalized();
    const Vec3 up = toEigen(viewport.camera().up());
    const Vec3 right = spec.viewDirection.cross(up).normalized();
    spec.viewUp = right.cross(spec.viewDirection);
    for (const QPointF& pixel : stroke) {
        const Vec3 p = toEigen(viewport.viewPlanePoint(pixel, centre)) - box.center();
        spec.viewStroke.emplace_back(p.dot(right), p.dot(spec.viewUp));
    }
    spec.style = (event->modifiers() & Qt::ShiftModifier) ? CutStyle::Sharp : CutStyle::Smooth;
    runUserAction(
        {}, [this](const QString& failure) { emit status(tr("Nothing cut: %1").arg(failure)); },
        [&] {
            auto command = model::CutPartCommand::create(document, part, spec);
            const QString text =
                tr("%1 in %2 ms (%3)")
                    .arg(command->text())
                    .arg(command->milliseconds(), 0, 'f', 0)
                    .arg(spec.style == CutStyle::Smooth ? tr("smooth face") : tr("flat face"));
            model::pushCommand(document, std::move(command));
            emit status(text);
        });
    viewport.update();
}

void CutTool::cancel(Viewport& viewport) {
    pixels_.clear();
    overlay_.clear();
    viewport.setStrokeOverlay({});
}

}  // namespace rigmesh::widgets
