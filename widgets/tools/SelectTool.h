// Select/Move tool: a click selects the joint or part under the cursor (or
// clears the selection); dragging a part moves it in the view plane, Ctrl +
// drag turns it about the view direction around its centre (tools/PartDrag).
// A drag is previewed live and pushed as one undo step on release.
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

  private:
    std::unique_ptr<PartDrag> drag_;
};

}  // namespace rigmesh::widgets
