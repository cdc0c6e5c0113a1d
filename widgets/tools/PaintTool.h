// Weight paint tool (W), in the manner of Blender's weight
// paint mode: drag over a part to paint the weight of the selected joint's
// bone (the one the Selected Bone weight view shows, which the tool turns
// on). Tool Options: Add, Subtract, Replace or Smooth, the falloff, the
// radius in screen pixels (its circle drawn at the cursor), strength, the
// Replace weight, front faces only (on by default: a brush never paints
// through a limb onto its far side) and X-mirror. Every dab auto-normalises
// and keeps the part's locked bones; a stroke is one undo step (one
// PaintWeightsCommand the recipe replays). A stroke paints the selected
// joint's part wherever it passes over it, and may start beside it. X-mirror
// paints the other side too, about the part's left-right mirror plane
// (rig/MirrorSymmetry). Ctrl + click samples: the
// vertex's weights are pinned in the Weights panel and the Replace weight
// becomes the bone's weight there (Blender's Sample Weight). Esc puts the
// stroke back.
#pragma once

#include <QObject>
#include <QPointF>
#include <memory>
#include <optional>
#include <vector>

#include "model/Document.h"
#include "model/preview/SkinningPreview.h"
#include "part/WeightPaint.h"
#include "viewport/ViewportTool.h"

class QDoubleSpinBox;

namespace rigmesh::widgets {

class PaintTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Paint Weights"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;
    void hover(Viewport& viewport, QMouseEvent* event) override;
    void addOverlay(const Viewport& viewport, ColouredVertices& lines) const override;
    QWidget* optionsWidget() override;
    // Painting shows what it paints: the selected bone's weights.
    std::optional<WeightView> weightView() const override;

    // The brush (options), for tests and the options widget.
    BrushMode mode = BrushMode::Add;
    BrushFalloff falloff = BrushFalloff::Smooth;
    bool frontFacesOnly = true;
    double radiusPixels = 40.0;
    double strength = 0.5;
    double value = 1.0;
    bool mirror = false;

  private:
    // A dab where the cursor is, if it is over the stroke's part.
    void dab(Viewport& viewport, const QPointF& pixel);
    // Ctrl + click: pins the vertex's weights and takes the bone's weight.
    void sample(Viewport& viewport, const QPointF& pixel);
    void endStroke();

    QWidget* options_ = nullptr;
    QDoubleSpinBox* valueBox_ = nullptr;
    // The stroke's live weights (model/preview/SkinningPreview.h).
    std::unique_ptr<model::SkinningPreview> stroke_;
    BoneId bone_ = 0;
    std::shared_ptr<Part> working_;           // with the stroke's dabs so far
    std::unique_ptr<WeightPainter> painter_;  // over working_'s mesh
    std::vector<WeightDab> dabs_;             // centres in document coordinates
    QPointF lastDab_;
    QPointF cursor_;
    bool cursorInView_ = false;
};

}  // namespace rigmesh::widgets
