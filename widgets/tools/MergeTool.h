// Merge tool (M), paper 3.2: drag a part into another. The merge is chosen
// where the part is dropped: the dragged joint nearest (on screen) to the
// other part's skeleton snaps onto that part's joint when one is within 30
// pixels of it, else splits that part's nearest bone where the joint fell
// (a split within a tenth of a bone's end snaps onto the end). The pair
// lights up (a line between them, crosses on both), the dragged part shows
// see-through in front of the other with a second copy where the merge puts
// it, and the status bar says what a release will do. Release opens a small
// menu: Snap, Split (the point where the joint fell) or Connect (a new bone
// between the joints), the suggested one active; hovering an item previews
// it, Esc or a click elsewhere puts the part back. Shift + release splits and
// Ctrl + release connects at once, without the menu. Esc during the drag (or
// a tool switch) puts the part back too. The move and the merge are one undo
// step; a refused merge puts the part back and says why.
#pragma once

#include <QObject>
#include <QPointer>
#include <optional>

#include "merge/SkeletonJoin.h"
#include "model/Document.h"
#include "model/PartNode.h"
#include "tools/PartDrag.h"
#include "viewport/ViewportTool.h"

class QMenu;

namespace rigmesh::widgets {

class MergeTool : public ViewportTool {
    Q_OBJECT
  public:
    using ViewportTool::ViewportTool;
    QString name() const override { return tr("Merge"); }
    QString hint() const override;
    void press(Viewport& viewport, QMouseEvent* event) override;
    void move(Viewport& viewport, QMouseEvent* event) override;
    void release(Viewport& viewport, QMouseEvent* event) override;
    void cancel(Viewport& viewport) override;
    void addOverlay(const Viewport& viewport, ColouredVertices& lines) const override;
    std::vector<PartInFront> partsInFront(const Viewport& viewport) const override;

    // The Snap / Split / Connect menu while it waits for a choice, else null.
    QMenu* choices() const;

  private:
    // The merge a release would make, in document coordinates.
    struct Candidate {
        model::PartId target = model::kNoPart;
        JointId draggedJoint = kNoJoint;
        JointId targetJoint = kNoJoint;  // nearest the drop on screen (snap, connect)
        JointId splitNear = kNoJoint;    // the bone end a split point lies close to
        Vec3 draggedPoint = Vec3::Zero();
        Vec3 jointPoint = Vec3::Zero();   // targetJoint
        Vec3 splitPoint = Vec3::Zero();   // on the target's bone, where the joint fell
        Vec3 targetPoint = Vec3::Zero();  // of the mode: jointPoint or splitPoint
        MergeMode mode = MergeMode::Snap;
        MergeMode preferred = MergeMode::Snap;  // what the drop point suggests
    };
    // The merge where the dragged part is, in the mode its drop suggests.
    std::optional<Candidate> findCandidate(const Viewport& viewport) const;
    // The candidate in `mode`.
    Candidate withMode(const model::Document& document, Candidate candidate, MergeMode mode) const;
    QString describe(const model::Document& document, model::PartId dragged,
                     const Candidate& candidate) const;
    // Opens the menu at `pixel`; the part stays where it was dropped.
    void offerChoices(Viewport& viewport, const QPointF& pixel);
    void choose(Viewport& viewport, std::optional<MergeMode> mode);
    // The drag is shared with the merge's background job, which commits or
    // reverts its preview when done.
    void merge(Viewport& viewport, std::shared_ptr<PartDrag> drag, const Candidate& candidate);
    void putBack(Viewport& viewport, PartDrag& drag);

    std::shared_ptr<PartDrag> drag_;
    std::optional<Candidate> candidate_;
    // A release waiting for the menu's choice: the dropped part's drag (its
    // candidate is candidate_).
    std::shared_ptr<PartDrag> pending_;
    QPointer<QMenu> choices_;
};

}  // namespace rigmesh::widgets
