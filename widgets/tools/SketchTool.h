// Sketch tool: drag with the left button to draw a silhouette on the plane
// through the scene centre facing the camera; on release the stroke is handed
// to `strokeFinished` in that plane's 2D coordinates with the plane's frame,
// which becomes the new part's placement (paper section 2: the part appears
// where it was drawn). A click or a tiny stroke only shows a hint. While the
// stroke is drawn, `strokeChanged` hands on the stroke so far, exactly as a
// release there would (its live preview: DocumentView), and
// `strokeAbandoned` says when it ends without a part.
#pragma once

#include <QObject>
#include <vector>

#include "model/PartNode.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

class SketchTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Sketch"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;

  signals:
    void strokeFinished(const std::vector<rigmesh::Vec2>& stroke,
                        const rigmesh::model::Placement& plane);
    void strokeChanged(const std::vector<rigmesh::Vec2>& stroke,
                       const rigmesh::model::Placement& plane);
    void strokeAbandoned();

  private:
    // The stroke drawn so far in the sketch plane's 2D frame, as a release
    // hands it on.
    std::vector<Vec2> planeStroke(const Viewport& viewport) const;
    // Where a pixel lies on the sketch plane.
    QVector3D onPlane(const Viewport& viewport, const QPointF& pixel) const;

    std::vector<QPointF> pixels_;
    // The plane the stroke is drawn on, taken at the press: the part it
    // previews must not move the plane (its origin is the scene's centre).
    model::Placement plane_;
    bool drawing_ = false;
};

}  // namespace rigmesh::widgets
