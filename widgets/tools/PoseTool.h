// Pose tool (paper section 3: the rig is there to be used while modelling).
// Every bone has its own rotation about its head (pose/Pose.h), so a drag
// moves only what hangs below what it turns. Drag a joint: inverse
// kinematics turns the bones from it up to the nearest junction, pinned
// joint or root (Alt: the root), bone lengths kept; the junction's other
// branches stay. Drag a bone anywhere along it, or Ctrl + drag the joint it
// ends at: forward kinematics, the bone turns about its head in the view
// plane, carrying only its descendants. A selected joint stands for the
// bone ending at it (as in the weight views; the root for the whole part):
// its rotation ring sits on that bone's head; drag it to turn the bone about
// the view axis (Blender's R). Shift + click a joint: pin or unpin it. Every
// drag is previewed live and pushed as one undo step on release.
#pragma once

#include <QObject>
#include <memory>
#include <optional>

#include "model/PartNode.h"
#include "model/preview/PosePreview.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

struct BoneHit;

class PoseTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Pose"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;
    void hover(Viewport& viewport, QMouseEvent* event) override;
    void addOverlay(const Viewport& viewport, ColouredVertices& lines) const override;
    // "Reach through the whole body" (what Alt does for one drag).
    QWidget* optionsWidget() override;

  private:
    // The head of the selected joint's bone (the root itself for the root),
    // about which the ring turns: its place on screen, when shown.
    std::optional<QPointF> ringCentre(const Viewport& viewport) const;
    bool onRing(const Viewport& viewport, const QPointF& pixel) const;
    void grabRing(Viewport& viewport, const QPointF& pixel);
    void grabBone(Viewport& viewport, const BoneHit& bone, const QPointF& pixel);
    void dragWithIk(Viewport& viewport, const QPointF& pixel);
    void rotateWithFk(Viewport& viewport, const QPointF& pixel);

    struct Drag {
        model::PartId part = model::kNoPart;
        // IK: the dragged joint. FK: the joint the turned bone ends at,
        // whose rotation it is (the root: the whole part).
        JointId joint = kNoJoint;
        QVector3D grabPoint;       // the joint's world position at the press
        bool forward = false;      // FK rotation rather than IK
        bool ring = false;         // FK by the selected joint's ring
        bool wholeBody = false;    // IK up to the root (Alt), not just this limb
        JointId pivot = kNoJoint;  // FK: the head of the turned bone (the root for the root)
        QPointF startPixel;
        Pose startPose;
    };
    void startDrag(model::Document& document, const Drag& drag);
    void endDrag();

    std::optional<Drag> drag_;
    // The drag's live pose (model/preview/PosePreview.h), while drag_ is set.
    std::unique_ptr<model::PosePreview> preview_;
    bool ringHovered_ = false;
    bool wholeBodyByDefault_ = false;
    QWidget* options_ = nullptr;  // owned by the options dock once shown
};

}  // namespace rigmesh::widgets
