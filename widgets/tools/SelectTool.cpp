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
    // Moving a part into another does not join them: say which tool does,
    // and show the part in front so it does not vanish inside the other.
    const model::Document& document = *viewport.document();
    const std::vector<model::PartId> under = drag_->overlapping(document);
    const bool overlapping = !under.empty();
    if (overlapping && !overlapping_)
        emit status(tr("%1 overlaps %2: moving does not join parts; the Merge tool (M) merges "
                       "them")
                        .arg(document.part(drag_->part()).name, document.part(under.front()).name));
    else if (!overlapping && overlapping_)
        emit status(hint());
    overlapping_ = overlapping;
}

void SelectTool::release(Viewport&, QMouseEvent*) {
    // One undo step per drag (an unmoved click pushes nothing).
    if (drag_)
        drag_->preview().commit();
    drag_.reset();
    overlapping_ = false;
}

void SelectTool::cancel(Viewport&) {
    // A drag cut short (tool switch) puts the part back.
    drag_.reset();
    overlapping_ = false;
}

std::vector<ViewportTool::PartInFront> SelectTool::partsInFront(const Viewport&) const {
    if (!drag_ || !overlapping_)
        return {};
    return {PartInFront{drag_->part(), std::nullopt}};
}

}  // namespace rigmesh::widgets
