#include "tools/SelectTool.h"

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
    drag_ = std::make_unique<PartDrag>(viewport, *part, event->position(),
                                       event->modifiers() & Qt::ControlModifier);
}

void SelectTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!drag_ || !(event->buttons() & Qt::LeftButton))
        return;
    drag_->dragTo(viewport, event->position());
}

void SelectTool::release(Viewport&, QMouseEvent*) {
    // One undo step per drag (an unmoved click pushes nothing).
    if (drag_)
        drag_->preview().commit();
    drag_.reset();
}

void SelectTool::cancel(Viewport&) {
    // A drag cut short (tool switch) puts the part back.
    drag_.reset();
}

}  // namespace rigmesh::widgets
