// Cut tool (C), paper 3.1: drag a stroke across a part, from outside it to
// outside it; on release the part is cut along the surface the stroke
// sweeps in the view direction (a plane for a straight stroke) into two
// rigged parts. The cut face is smooth
// (tangent-continuous); Shift + release makes it flat (a crease). A stroke
// that does not cross a part completely cuts nothing and says so. One undo
// step.
#pragma once

#include <QObject>
#include <QPointF>
#include <QVector3D>
#include <vector>

#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

class CutTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Cut"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;

  private:
    std::vector<QPointF> pixels_;
    // The drawn line on the view plane through the scene's centre, taken at
    // the press: one point per move, not the whole line re-projected (each
    // projection measures the whole scene, Viewport::sketchPlanePoint).
    QVector3D planePoint_;
    std::vector<QVector3D> overlay_;
};

}  // namespace rigmesh::widgets
