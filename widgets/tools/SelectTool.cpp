#include "tools/SelectTool.h"

#include "base/Error.h"
#include "model/commands/MovePartCommand.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

QString SelectTool::hint() const {
    return tr(
        "Select: click a part or a joint; drag a part to move it; middle drag orbits, Shift + "
        "middle drag pans, wheel zooms");
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
    dragged_ = part;
    grabPoint_ =
        viewport.sketchPlanePoint(event->position());  // the plane stays fixed during the drag
    startPlacement_ = document.part(*part).placement;
}

void SelectTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!dragged_ || !(event->buttons() & Qt::LeftButton))
        return;
    model::Document& document = *viewport.document();
    if (!document.contains(*dragged_)) {
        dragged_.reset();
        return;
    }
    const QVector3D now = viewport.viewPlanePoint(event->position(), grabPoint_);
    model::Placement target = startPlacement_;
    target.translation +=
        Vec3(now.x() - grabPoint_.x(), now.y() - grabPoint_.y(), now.z() - grabPoint_.z());
    // Consecutive moves of one part merge into a single undo step (mergeWith).
    document.undoStack()->push(new model::MovePartCommand(document, *dragged_, target));
}

void SelectTool::release(Viewport&, QMouseEvent*) {
    dragged_.reset();
}

void SelectTool::cancel(Viewport&) {
    dragged_.reset();
}

}  // namespace rigmesh::widgets
