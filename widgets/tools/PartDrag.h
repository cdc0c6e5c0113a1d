// A part moved by the mouse, as the Select and Merge tools drag it: the
// grabbed point follows the cursor on the view plane through it, or (turning)
// the part turns about the view direction through its centre by the angle
// the cursor sweeps round that centre on screen. Shown live through a
// model::PlacementPreview, which commits the drag as one undo step or puts
// the part back.
#pragma once

#include <QPointF>
#include <QVector3D>
#include <vector>

#include "model/preview/PlacementPreview.h"

namespace rigmesh::widgets {

class Viewport;

class PartDrag {
  public:
    // Grabs `part` (a part of the viewport's document) at `pixel`.
    PartDrag(Viewport& viewport, model::PartId part, const QPointF& pixel, bool turning);

    model::PartId part() const { return preview_.partId(); }
    // Previews the placement the cursor at `pixel` gives.
    void dragTo(const Viewport& viewport, const QPointF& pixel);
    model::PlacementPreview& preview() { return preview_; }
    // The other visible parts the dragged one overlaps (their boxes meet:
    // the paper's "close proximity" for a merge, 3.2), in document order.
    std::vector<model::PartId> overlapping(const model::Document& document) const;

  private:
    model::PlacementPreview preview_;
    QVector3D grabPoint_;  // on the plane that stays fixed during the drag
    QPointF grabPixel_;
    bool turning_;
};

}  // namespace rigmesh::widgets
