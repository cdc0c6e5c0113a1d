// Merge tool (M), paper 3.2: drag a part near another; the nearest pair of
// joints lights up (a line between them, crosses on both) and the status bar
// says what a release will do. Release merges: snap by default, Shift +
// release splits the other part's bone under the dragged joint, Ctrl +
// release connects the two joints by a new bone. Esc (or a tool switch)
// puts the part back. The move and the merge are one undo step; a refused
// merge puts the part back and says why.
#pragma once

#include <QObject>
#include <optional>

#include "merge/SkeletonJoin.h"
#include "model/Document.h"
#include "model/PartNode.h"
#include "viewport/ViewportTool.h"

namespace rigmesh::widgets {

class MergeTool : public QObject, public ViewportTool {
    Q_OBJECT
  public:
    using QObject::QObject;
    QString name() const override { return tr("Merge"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;
    void addOverlay(const Viewport& viewport, ColouredVertices& lines) const override;

  private:
    // The merge a release would make, in document coordinates.
    struct Candidate {
        model::PartId target = model::kNoPart;
        JointId draggedJoint = kNoJoint;
        JointId targetJoint = kNoJoint;
        Vec3 draggedPoint, targetPoint;  // the joints (split: the point on the bone)
        MergeMode mode = MergeMode::Snap;
    };
    std::optional<Candidate> findCandidate(const Viewport& viewport,
                                           Qt::KeyboardModifiers modifiers) const;
    QString describe(const model::Document& document, const Candidate& candidate) const;

    std::optional<model::PartId> dragged_;
    QVector3D grabPoint_;
    model::Placement startPlacement_;
    std::optional<Candidate> candidate_;
};

}  // namespace rigmesh::widgets
