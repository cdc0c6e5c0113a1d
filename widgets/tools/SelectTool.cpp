#include "tools/SelectTool.h"

#include <Eigen/Geometry>
#include <cmath>

#include "base/Error.h"
#include "model/commands/MovePartCommand.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

QString SelectTool::hint() const {
    return tr(
        "Select: click a part or a joint (with a weight view on, the click pins the vertex's "
        "weights in the Skin Weights panel); drag a part to move it, Ctrl + drag to turn it");
}

void SelectTool::press(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    if (auto joint = viewport.jointAt(event->position())) {
        document.setSelection(*joint);
        return;
    }
    auto part = viewport.partAt(event->position());
    if (!part) {
        document.clearSelection();
        return;
    }
    document.setSelection({*part, kNoJoint});
    // With a weight view on, a click also pins the vertex's weights in the
    // Weights panel.
    if (viewport.weightView() != WeightView::Off)
        if (const auto hit = viewport.surfaceAt(event->position()))
            viewport.setInspectedVertex(*hit);
    dragged_ = part;
    grabPoint_ =
        viewport.sketchPlanePoint(event->position());  // the plane stays fixed during the drag
    startPlacement_ = document.part(*part).placement;
    grabPixel_ = event->position();
    rotating_ = event->modifiers() & Qt::ControlModifier;
}

void SelectTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!dragged_ || !(event->buttons() & Qt::LeftButton))
        return;
    model::Document& document = *viewport.document();
    if (!document.contains(*dragged_)) {
        dragged_.reset();
        return;
    }
    model::Placement target = startPlacement_;
    if (rotating_) {
        // Turn about the view direction through the part's centre by the
        // angle the cursor swept around that centre on screen.
        const model::PartNode& node = document.part(*dragged_);
        Eigen::AlignedBox3d box;
        for (const Vec3& v : node.part->mesh.vertices)
            box.extend(v);
        const Vec3 centre = startPlacement_.rotation * box.center() + startPlacement_.translation;
        const QVector3D screen = viewport.camera().project(toQt(centre), QSizeF(viewport.size()));
        const double sweep =
            screenSweep(QPointF(screen.x(), screen.y()), grabPixel_, event->position());
        const Eigen::Quaterniond turn(
            Eigen::AngleAxisd(sweep, toEigen(viewport.camera().forward())));
        target.rotation = (turn * startPlacement_.rotation).normalized();
        target.translation = turn * (startPlacement_.translation - centre) + centre;
    } else {
        const QVector3D now = viewport.viewPlanePoint(event->position(), grabPoint_);
        target.translation += toEigen(now - grabPoint_);
    }
    // A live preview; the drag becomes one command on release.
    document.setPlacement(*dragged_, target);
}

void SelectTool::release(Viewport& viewport, QMouseEvent*) {
    model::Document& document = *viewport.document();
    if (dragged_ && document.contains(*dragged_)) {
        // One undo step per drag, already applied by the preview (an
        // unmoved click pushes an obsolete command, which the stack drops).
        document.undoStack()->push(new model::MovePartCommand(
            document, *dragged_, startPlacement_, document.part(*dragged_).placement, true));
    }
    dragged_.reset();
}

void SelectTool::cancel(Viewport& viewport) {
    // A drag cut short (tool switch) puts the part back.
    if (dragged_ && viewport.document()->contains(*dragged_))
        viewport.document()->setPlacement(*dragged_, startPlacement_);
    dragged_.reset();
}

}  // namespace rigmesh::widgets
