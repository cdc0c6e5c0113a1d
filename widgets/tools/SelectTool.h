// Select/Move tool: a click selects the joint or part under the cursor (or
// clears the selection); dragging a part moves it in the view plane, Ctrl +
// drag turns it about the view direction around its centre. A drag is one
// undo step: every move pushes a MovePartCommand that merges with the
// previous one of the same part.
#pragma once

#include <QObject>
#include <optional>

#include "model/PartNode.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

class SelectTool : public QObject, public ViewportTool {
    Q_OBJECT
  public:
    using QObject::QObject;
    QString name() const override { return tr("Select"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;

  private:
    std::optional<model::PartId> dragged_;
    QVector3D grabPoint_;
    QPointF grabPixel_;
    bool rotating_ = false;
    model::Placement startPlacement_;
};

}  // namespace rigmesh::widgets
