#include "tools/CutTool.h"

#include <Eigen/Geometry>
#include <map>

#include "base/Error.h"
#include "model/commands/CutPartCommand.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// A stroke shorter than this on screen is a click.
constexpr double kMinimumPixels = 20.0;
constexpr int kSamples = 64;

}  // namespace

QString CutTool::hint() const {
    return tr(
        "Cut: drag a line across a part, from outside it to outside it; release cuts it in two "
        "with a smooth face, Shift + release with a flat one; Esc cancels");
}

void CutTool::press(Viewport& viewport, QMouseEvent* event) {
    pixels_ = {event->position()};
    viewport.setStrokeOverlay({viewport.sketchPlanePoint(event->position())});
}

void CutTool::move(Viewport& viewport, QMouseEvent* event) {
    if (pixels_.empty() || !(event->buttons() & Qt::LeftButton))
        return;
    pixels_.resize(1);
    pixels_.push_back(event->position());
    // The cut is the straight line from where the drag began.
    viewport.setStrokeOverlay(
        {viewport.sketchPlanePoint(pixels_.front()), viewport.sketchPlanePoint(pixels_.back())});
}

void CutTool::release(Viewport& viewport, QMouseEvent* event) {
    if (pixels_.empty())
        return;
    const QPointF a = pixels_.front();
    const QPointF b = event->position();
    pixels_.clear();
    viewport.setStrokeOverlay({});
    if (QLineF(a, b).length() < kMinimumPixels)
        return;  // a click
    // The part the line crosses most, which neither end may touch (paper
    // 3.1: the stroke must cross the silhouette completely).
    std::map<model::PartId, int> crossed;
    for (int i = 1; i < kSamples; ++i)
        if (auto part = viewport.partAt(a + (b - a) * (static_cast<double>(i) / kSamples)))
            ++crossed[*part];
    if (crossed.empty()) {
        emit viewport.statusMessage(tr("Nothing cut: the line does not cross a part"));
        return;
    }
    const model::PartId part =
        std::max_element(crossed.begin(), crossed.end(), [](const auto& x, const auto& y) {
            return x.second < y.second;
        })->first;
    if (viewport.partAt(a) == part || viewport.partAt(b) == part) {
        emit viewport.statusMessage(
            tr("Nothing cut: draw the line across the whole part, from outside it to outside it"));
        return;
    }
    model::Document& document = *viewport.document();
    const model::PartNode& node = document.part(part);
    Eigen::AlignedBox3d box;
    for (const Vec3& v : node.part->mesh.vertices)
        box.extend(node.placement.rotation * v + node.placement.translation);
    const QVector3D centre = toQt(box.center());
    const Vec3 from = toEigen(viewport.viewPlanePoint(a, centre));
    const Vec3 to = toEigen(viewport.viewPlanePoint(b, centre));
    model::CutSpec spec;
    spec.point = from;
    spec.normal = (to - from).cross(toEigen(viewport.camera().forward()));
    spec.style = (event->modifiers() & Qt::ShiftModifier) ? CutStyle::Sharp : CutStyle::Smooth;
    try {
        auto command = model::CutPartCommand::create(document, part, spec);
        const QString text =
            tr("%1 in %2 ms (%3)")
                .arg(command->text())
                .arg(command->milliseconds(), 0, 'f', 0)
                .arg(spec.style == CutStyle::Smooth ? tr("smooth face") : tr("flat face"));
        document.undoStack()->push(command.release());
        emit viewport.statusMessage(text);
    } catch (const Error& error) {
        emit viewport.statusMessage(
            tr("Nothing cut: %1").arg(QString::fromStdString(error.what())));
    }
    viewport.update();
}

void CutTool::cancel(Viewport& viewport) {
    pixels_.clear();
    viewport.setStrokeOverlay({});
}

}  // namespace rigmesh::widgets
