// Select/Move tool: a click selects the joint or part under the cursor (or
// clears the selection); dragging a part moves it in the view plane, Ctrl +
// drag turns it about the view direction around its centre (tools/PartDrag).
// A drag is previewed live and pushed as one undo step on release. A part
// dragged over another shows in front of it, and the status bar says that
// the Merge tool joins parts (moving never does).
#pragma once

#include <QObject>
#include <memory>

#include "tools/PartDrag.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

class SelectTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Select"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;
    std::vector<PartInFront> partsInFront(const Viewport& viewport) const override;

  private:
    std::unique_ptr<PartDrag> drag_;
    bool overlapping_ = false;  // the dragged part overlaps another
};

}  // namespace rigmesh::widgets
