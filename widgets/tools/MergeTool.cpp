#include "tools/MergeTool.h"

#include <Eigen/Geometry>
#include <QElapsedTimer>
#include <QMenu>
#include <QPointer>
#include <memory>
#include <utility>

#include "UserAction.h"
#include "base/Error.h"
#include "jobs/JobRunner.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/MergePartsCommand.h"
#include "model/commands/MovePartCommand.h"
#include "rig/BoneSegment.h"
#include "viewport/RenderScene.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

// A dropped joint this close (pixels) to a joint of the other part snaps
// onto it; farther, the other part's bone is split where the joint fell.
constexpr double kSnapPixels = 30.0;
// A split within this fraction of a bone's length from its end snaps onto
// that end instead.
constexpr double kSplitEnds = 0.1;

bool rigged(const model::PartNode& node) {
    return node.part && node.part->skeleton.boneCount() > 0;
}

// The parameter (0..1) of the point of `bone` nearest the line through
// `point` along `direction`: the closest points of two lines, the bone's
// clamped to its ends. A bone along the line (all its points equally near)
// answers `along`.
double boneParameterNearestLine(const BoneSegment& bone, const Vec3& point, const Vec3& direction,
                                double along) {
    const Vec3 axis = bone.tail - bone.head;
    const Vec3 d = direction.normalized();
    const Vec3 w = bone.head - point;
    const double a = axis.squaredNorm(), b = axis.dot(d);
    const double denominator = a - b * b;  // |axis|^2 |d|^2 - (axis.d)^2, |d| = 1
    if (!(denominator > 1e-12 * a))
        return along;
    return std::clamp((b * d.dot(w) - axis.dot(w)) / denominator, 0.0, 1.0);
}

void addCross(ColouredVertices& lines, const Vec3& at, double size, const QVector3D& colour) {
    for (int axis = 0; axis < 3; ++axis) {
        const Vec3 d = Vec3::Unit(axis) * size;
        lines.add(toQt(at - d), colour);
        lines.add(toQt(at + d), colour);
    }
}

}  // namespace

QString MergeTool::hint() const {
    return tr(
        "Merge: drag a part into another; release over the lit joints to snap, split or "
        "connect them (Shift + release splits, Ctrl + release connects at once); Esc cancels");
}

void MergeTool::press(Viewport& viewport, QMouseEvent* event) {
    if (pending_)
        choose(viewport, std::nullopt);  // a click beside the open menu
    model::Document& document = *viewport.document();
    auto part = viewport.partAt(event->position());
    if (!part) {
        document.clearSelection();
        return;
    }
    document.setSelection({*part, kNoJoint});
    drag_ = std::make_shared<PartDrag>(viewport, *part, event->position(), false);
    candidate_.reset();
}

namespace {

// Shift: split, Ctrl: connect; none: ask.
std::optional<MergeMode> modeOf(Qt::KeyboardModifiers modifiers) {
    if (modifiers & Qt::ControlModifier)
        return MergeMode::Connect;
    if (modifiers & Qt::ShiftModifier)
        return MergeMode::Split;
    return std::nullopt;
}

}  // namespace

void MergeTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!drag_ || !(event->buttons() & Qt::LeftButton))
        return;
    model::Document& document = *viewport.document();
    if (!document.contains(drag_->part())) {
        drag_.reset();
        return;
    }
    drag_->dragTo(viewport, event->position());
    candidate_ = findCandidate(viewport);
    if (candidate_)
        candidate_ = withMode(document, *candidate_,
                              modeOf(event->modifiers()).value_or(candidate_->preferred));
    // What a release here suggests (the menu offers the others too).
    emit status(candidate_ ? describe(document, drag_->part(), *candidate_)
                           : tr("Drag the part into another to merge them"));
}

std::optional<MergeTool::Candidate> MergeTool::findCandidate(const Viewport& viewport) const {
    const model::Document& document = *viewport.document();
    const model::PartNode& dragged = document.part(drag_->part());
    if (!rigged(dragged))
        return std::nullopt;
    const QSizeF size(viewport.size());
    auto screen = [&](const Vec3& p) {
        const QVector3D s = viewport.camera().project(toQt(p), size);
        return QPointF(s.x(), s.y());
    };
    // The dragged joint is the one nearest (on screen) to another part's
    // skeleton: where the part was dropped.
    std::optional<Candidate> best;
    double bestDistance = 0.0;
    for (const model::PartId id : drag_->overlapping(document)) {
        const model::PartNode& node = document.part(id);
        if (!rigged(node))
            continue;
        const Skeleton& target = node.part->skeleton;
        for (const Joint& from : dragged.part->skeleton.joints()) {
            const Vec3 a = dragged.placement.toWorld(from.position);
            const QPointF at = screen(a);
            // The line of sight through the dragged joint: every point on it
            // shows where the joint is on screen.
            const Vec3 sight = viewport.camera().orthographic()
                                   ? toEigen(viewport.camera().forward())
                                   : Vec3(a - toEigen(viewport.camera().eye()));
            for (const Bone& bone : target.bones()) {
                const Vec3 head = node.placement.toWorld(target.joint(bone.head).position);
                const Vec3 tail = node.placement.toWorld(target.joint(bone.tail).position);
                // The bone nearest on screen is the one dropped on.
                const QPointF h = screen(head), t = screen(tail);
                const QPointF ht = t - h;
                const double length2 = QPointF::dotProduct(ht, ht);
                const double onScreen =
                    length2 > 0.0 ? std::clamp(QPointF::dotProduct(at - h, ht) / length2, 0.0, 1.0)
                                  : 0.0;
                const double d = QLineF(at, h + onScreen * ht).length();
                if (best && d >= bestDistance)
                    continue;
                // Where it is split: its point nearest the line of sight, in
                // 3D (a parameter on screen is not one on the bone in
                // perspective: the far half of a bone looks shorter).
                const double u = boneParameterNearestLine({head, tail}, a, sight, onScreen);
                bestDistance = d;
                best = Candidate{};
                best->target = id;
                best->draggedJoint = from.id;
                best->draggedPoint = a;
                best->splitPoint = head + u * (tail - head);
                // A split this near a bone's end would leave a stub: the
                // end is snapped onto instead.
                best->splitNear = u < kSplitEnds         ? bone.head
                                  : u > 1.0 - kSplitEnds ? bone.tail
                                                         : kNoJoint;
            }
        }
    }
    if (!best)
        return std::nullopt;
    // The target's joint nearest the drop on screen: snapped onto when
    // within the snap radius, else the bone is split where the joint fell.
    const model::PartNode& node = document.part(best->target);
    const QPointF drop = screen(best->draggedPoint);
    double nearest = -1.0;
    for (const Joint& to : node.part->skeleton.joints()) {
        const Vec3 b = node.placement.toWorld(to.position);
        const double d = QLineF(drop, screen(b)).length();
        if (nearest < 0.0 || d < nearest) {
            nearest = d;
            best->targetJoint = to.id;
            best->jointPoint = b;
        }
    }
    if (nearest <= kSnapPixels) {
        best->preferred = MergeMode::Snap;
    } else if (best->splitNear != kNoJoint) {
        best->targetJoint = best->splitNear;
        best->jointPoint =
            node.placement.toWorld(node.part->skeleton.joint(best->splitNear).position);
        best->preferred = MergeMode::Snap;
    } else {
        best->preferred = MergeMode::Split;
    }
    return withMode(document, *best, best->preferred);
}

MergeTool::Candidate MergeTool::withMode(const model::Document&, Candidate candidate,
                                         MergeMode mode) const {
    candidate.mode = mode;
    candidate.targetPoint = mode == MergeMode::Split ? candidate.splitPoint : candidate.jointPoint;
    return candidate;
}

QString MergeTool::describe(const model::Document& document, model::PartId dragged,
                            const Candidate& c) const {
    const QString from = document.part(dragged).name;
    const QString into = document.part(c.target).name;
    switch (c.mode) {
        case MergeMode::Snap:
            return tr("Snap %1 of %2 onto %3 of %4 (Esc: cancel)")
                .arg(model::jointDisplayName(c.draggedJoint), from,
                     model::jointDisplayName(c.targetJoint), into);
        case MergeMode::Split:
            return tr("Split a bone of %1 and snap %2 of %3 there (Esc: cancel)")
                .arg(into, model::jointDisplayName(c.draggedJoint), from);
        case MergeMode::Connect:
            return tr("Connect %1 of %2 to %3 of %4 by a new bone (Esc: cancel)")
                .arg(model::jointDisplayName(c.draggedJoint), from,
                     model::jointDisplayName(c.targetJoint), into);
    }
    return {};
}

void MergeTool::release(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    if (!drag_ || !document.contains(drag_->part())) {
        drag_.reset();
        return;
    }
    drag_->dragTo(viewport, event->position());
    std::optional<Candidate> candidate = findCandidate(viewport);
    if (!candidate) {
        // Not near another part: an ordinary move, one undo step.
        drag_->preview().commit();
        drag_.reset();
        candidate_.reset();
        viewport.update();
        return;
    }
    if (const std::optional<MergeMode> mode = modeOf(event->modifiers())) {
        candidate_.reset();
        merge(viewport, std::exchange(drag_, nullptr), withMode(document, *candidate, *mode));
        return;
    }
    candidate_ = candidate;
    offerChoices(viewport, event->position());
}

QMenu* MergeTool::choices() const {
    return choices_;
}

void MergeTool::offerChoices(Viewport& viewport, const QPointF& pixel) {
    pending_ = std::exchange(drag_, nullptr);  // no more drag; the overlay stays on the candidate
    auto* menu = new QMenu(&viewport);
    menu->setAttribute(Qt::WA_DeleteOnClose);
    const QPointer<Viewport> view(&viewport);
    const std::pair<MergeMode, QString> items[] = {
        {MergeMode::Snap, tr("&Snap the joints together")},
        {MergeMode::Split, tr("S&plit the bone here")},
        {MergeMode::Connect, tr("&Connect by a new bone")}};
    // The item for what the drop point suggests is active: Enter takes it.
    QAction* first = nullptr;
    for (const auto& [mode, text] : items) {
        QAction* action = menu->addAction(text);
        action->setData(static_cast<int>(mode));
        if (!first || (candidate_ && mode == candidate_->preferred))
            first = action;
        // Hovering an item previews it: the lit joints or point and the status.
        connect(action, &QAction::hovered, this, [this, view, mode = mode] {
            if (!view || !pending_ || !candidate_ || !view->document()->contains(pending_->part()))
                return;
            candidate_ = withMode(*view->document(), *candidate_, mode);
            emit status(describe(*view->document(), pending_->part(), *candidate_));
            view->update();
        });
        connect(action, &QAction::triggered, this, [this, view, mode = mode] {
            if (view)
                choose(*view, mode);
        });
    }
    menu->addSeparator();
    connect(menu->addAction(tr("Cancel (Esc)")), &QAction::triggered, this, [this, view] {
        if (view)
            choose(*view, std::nullopt);
    });
    // Esc or a click elsewhere closes the menu without a choice; a choice
    // hides it first and is made before this queued check runs.
    connect(menu, &QMenu::aboutToHide, this, [this, view] {
        QMetaObject::invokeMethod(
            this,
            [this, view] {
                if (view && pending_)
                    choose(*view, std::nullopt);
            },
            Qt::QueuedConnection);
    });
    choices_ = menu;
    menu->setActiveAction(first);
    menu->popup(viewport.mapToGlobal(pixel.toPoint()));
    viewport.update();
}

void MergeTool::choose(Viewport& viewport, std::optional<MergeMode> mode) {
    if (!pending_)
        return;
    std::shared_ptr<PartDrag> drag = std::exchange(pending_, nullptr);
    const std::optional<Candidate> candidate = candidate_;
    candidate_.reset();
    if (choices_)
        choices_->close();
    if (!viewport.document()->contains(drag->part()))
        return;
    if (!mode || !candidate) {
        putBack(viewport, *drag);
        return;
    }
    merge(viewport, std::move(drag), withMode(*viewport.document(), *candidate, *mode));
}

void MergeTool::merge(Viewport& viewport, std::shared_ptr<PartDrag> drag,
                      const Candidate& candidate) {
    model::Document& document = *viewport.document();
    const model::PartId dragged = drag->part();
    model::MergeSpec spec;
    spec.mode = candidate.mode;
    spec.draggedJoint = candidate.draggedJoint;
    spec.target = candidate.mode == MergeMode::Split ? model::JointChoice(candidate.targetPoint)
                                                     : model::JointChoice(candidate.targetJoint);
    const model::PartId target = candidate.target;
    auto timer = std::make_shared<QElapsedTimer>();
    timer->start();
    QPointer<Viewport> view(&viewport);
    QPointer<model::Document> guarded(&document);
    QPointer<MergeTool> self(this);
    // Puts the dragged part back where the drag started (a refused or
    // cancelled merge leaves the document as it was).
    auto putBackTo = [view, self, drag](const QString& message) {
        drag->preview().revert();
        if (self)
            emit self->status(message);
        if (view)
            view->update();
    };
    // A merge of large parts takes long (the union, the local re-skin): it
    // runs as a background job on copies of the two nodes,
    // and the command is made and pushed when it is done.
    const model::PartNode draggedNode = document.part(dragged);
    const model::PartNode targetNode = document.part(target);
    JobRunner::runOn(
        viewport.jobRunner(),
        tr("Merging %1 into %2").arg(document.part(dragged).name, document.part(target).name),
        [draggedNode, targetNode, dragged, target, spec, guarded, view, self, drag, putBackTo,
         timer]() -> JobRunner::Apply {
            auto computed = std::make_shared<model::ComputedMerge>(
                model::MergePartsCommand::compute(draggedNode, targetNode, spec));
            return [=]() {
                if (!guarded)
                    return;
                QString summary;
                const bool merged = runUserAction(
                    {},
                    [&](const QString& failure) { putBackTo(tr("Not merged: %1").arg(failure)); },
                    [&] {
                        auto merge = model::MergePartsCommand::fromComputed(
                            *guarded, dragged, target, std::move(*computed));
                        summary = merge->summary();
                        // The drop and the merge are one step: undo puts both
                        // parts back where they were before the drag.
                        // Pushed on the document as it was before the drag,
                        // where a failure leaves it (the preview put back).
                        model::PlacementPreview& preview = drag->preview();
                        const model::Placement from = preview.original();
                        const model::Placement to = preview.current();
                        const bool moved = preview.previewing() && !(from == to);
                        preview.revert();
                        model::pushMacro(*guarded, merge->text(), [&] {
                            if (moved)
                                model::pushCommand(
                                    *guarded,
                                    std::make_unique<model::MovePartCommand>(
                                        *guarded, dragged, from, to, model::CommandMerging::Never));
                            model::pushCommand(*guarded, std::move(merge));
                        });
                    });
                if (!merged)
                    return;
                guarded->setSelection({target, kNoJoint});
                if (self)
                    emit self->status(tr("%1 (%2 ms in all)").arg(summary).arg(timer->elapsed()));
                if (view)
                    view->update();
            };
        },
        [putBackTo](const QString& reason) { putBackTo(tr("Not merged: %1").arg(reason)); },
        [putBackTo]() { putBackTo(tr("Merge cancelled")); });
    viewport.update();
}

void MergeTool::putBack(Viewport& viewport, PartDrag& drag) {
    drag.preview().revert();
    emit status(tr("Merge cancelled"));
    viewport.update();
}

void MergeTool::cancel(Viewport& viewport) {
    if (pending_) {
        choose(viewport, std::nullopt);
    } else if (drag_ && viewport.document()->contains(drag_->part())) {
        putBack(viewport, *drag_);
    }
    drag_.reset();
    candidate_.reset();
}

std::vector<ViewportTool::PartInFront> MergeTool::partsInFront(const Viewport& viewport) const {
    const std::shared_ptr<PartDrag>& drag = drag_ ? drag_ : pending_;
    if (!drag || !viewport.document()->contains(drag->part()))
        return {};
    // See-through and in front of the part it goes into, and a second copy
    // where the merge would put it (snap and split move it onto the joint).
    PartInFront shown{drag->part(), std::nullopt};
    if (candidate_ && candidate_->mode != MergeMode::Connect)
        shown.resultOffset = candidate_->targetPoint - candidate_->draggedPoint;
    return {shown};
}

void MergeTool::addOverlay(const Viewport& viewport, ColouredVertices& lines) const {
    const std::shared_ptr<PartDrag>& drag = drag_ ? drag_ : pending_;
    if (!candidate_ || !drag || !viewport.document()->contains(drag->part()))
        return;
    const std::optional<model::PartId> part = drag->part();
    const QVector3D lit(0.2f, 0.75f, 1.0f);
    const double size =
        0.03 * model::worldBounds(viewport.document()->part(*part)).diagonal().norm();
    lines.add(toQt(candidate_->draggedPoint), lit);
    lines.add(toQt(candidate_->targetPoint), lit);
    addCross(lines, candidate_->draggedPoint, size, lit);
    addCross(lines, candidate_->targetPoint, size, lit);
}

}  // namespace rigmesh::widgets
