#include "tools/MergeTool.h"

#include <Eigen/Geometry>
#include <QElapsedTimer>

#include "base/Error.h"
#include "model/ErrorText.h"
#include "model/commands/MergePartsCommand.h"
#include "model/commands/MovePartCommand.h"
#include "rig/BoneSegment.h"
#include "viewport/RenderScene.h"
#include "viewport/ViewMath.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

Vec3 toWorld(const model::Placement& placement, const Vec3& p) {
    return placement.rotation * p + placement.translation;
}

Eigen::AlignedBox3d worldBox(const model::PartNode& node) {
    Eigen::AlignedBox3d box;
    for (const Vec3& v : node.part->mesh.vertices)
        box.extend(toWorld(node.placement, v));
    return box;
}

bool rigged(const model::PartNode& node) {
    return node.part && node.part->skeleton.boneCount() > 0;
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
        "Merge: drag a part into another; release snaps the lit joints together, Shift + "
        "release splits the other part's bone there, Ctrl + release connects them by a new "
        "bone; Esc cancels");
}

void MergeTool::press(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    auto part = viewport.partAt(event->position());
    if (!part) {
        document.clearSelection();
        return;
    }
    document.setSelection({*part, kNoJoint});
    dragged_ = part;
    grabPoint_ = viewport.sketchPlanePoint(event->position());
    startPlacement_ = document.part(*part).placement;
    candidate_.reset();
}

void MergeTool::move(Viewport& viewport, QMouseEvent* event) {
    if (!dragged_ || !(event->buttons() & Qt::LeftButton))
        return;
    model::Document& document = *viewport.document();
    if (!document.contains(*dragged_)) {
        dragged_.reset();
        return;
    }
    model::Placement target = startPlacement_;
    target.translation +=
        toEigen(viewport.viewPlanePoint(event->position(), grabPoint_) - grabPoint_);
    document.setPlacement(*dragged_, target);  // a live preview
    candidate_ = findCandidate(viewport, event->modifiers());
    emit viewport.statusMessage(candidate_ ? describe(document, *candidate_)
                                           : tr("Drag the part into another to merge them"));
}

std::optional<MergeTool::Candidate> MergeTool::findCandidate(
    const Viewport& viewport, Qt::KeyboardModifiers modifiers) const {
    const model::Document& document = *viewport.document();
    const model::PartNode& dragged = document.part(*dragged_);
    if (!rigged(dragged))
        return std::nullopt;
    const Eigen::AlignedBox3d draggedBox = worldBox(dragged);
    std::optional<Candidate> best;
    double bestDistance = 0.0;
    for (const model::PartNode& node : document.parts()) {
        // "Close proximity" (paper 3.2): the parts' boxes overlap.
        if (node.id == dragged.id || !node.visible || !rigged(node) ||
            !worldBox(node).intersects(draggedBox))
            continue;
        for (const Joint& from : dragged.part->skeleton.joints())
            for (const Joint& to : node.part->skeleton.joints()) {
                const Vec3 a = toWorld(dragged.placement, from.position);
                const Vec3 b = toWorld(node.placement, to.position);
                const double d = (a - b).norm();
                if (!best || d < bestDistance) {
                    best = Candidate{node.id, from.id, to.id, a, b, MergeMode::Snap};
                    bestDistance = d;
                }
            }
    }
    if (!best)
        return best;
    if (modifiers & Qt::ControlModifier) {
        best->mode = MergeMode::Connect;
    } else if (modifiers & Qt::ShiftModifier) {
        // The dragged joint projected on the other part's nearest bone.
        best->mode = MergeMode::Split;
        const model::PartNode& target = document.part(best->target);
        double nearest = -1.0;
        for (const BoneSegment& bone : target.part->boneSegments()) {
            const BoneSegment world{toWorld(target.placement, bone.head),
                                    toWorld(target.placement, bone.tail)};
            const Vec3 p = closestPointOnSegment(best->draggedPoint, world);
            const double d = (p - best->draggedPoint).norm();
            if (nearest < 0.0 || d < nearest) {
                nearest = d;
                best->targetPoint = p;
            }
        }
    }
    return best;
}

QString MergeTool::describe(const model::Document& document, const Candidate& c) const {
    const QString from = document.part(*dragged_).name;
    const QString into = document.part(c.target).name;
    switch (c.mode) {
        case MergeMode::Snap:
            return tr("Release to snap %1 of %2 onto %3 of %4 (Shift: split, Ctrl: connect, Esc: "
                      "cancel)")
                .arg(model::jointDisplayName(c.draggedJoint), from,
                     model::jointDisplayName(c.targetJoint), into);
        case MergeMode::Split:
            return tr("Release to split a bone of %1 and snap %2 of %3 there (Esc: cancel)")
                .arg(into, model::jointDisplayName(c.draggedJoint), from);
        case MergeMode::Connect:
            return tr("Release to connect %1 of %2 to %3 of %4 by a new bone (Esc: cancel)")
                .arg(model::jointDisplayName(c.draggedJoint), from,
                     model::jointDisplayName(c.targetJoint), into);
    }
    return {};
}

void MergeTool::release(Viewport& viewport, QMouseEvent* event) {
    model::Document& document = *viewport.document();
    if (!dragged_ || !document.contains(*dragged_)) {
        dragged_.reset();
        return;
    }
    const model::PartId dragged = *dragged_;
    dragged_.reset();
    const std::optional<Candidate> candidate = findCandidate(viewport, event->modifiers());
    candidate_.reset();
    const model::Placement dropped = document.part(dragged).placement;
    if (!candidate) {
        // Not near another part: an ordinary move, one undo step.
        document.undoStack()->push(
            new model::MovePartCommand(document, dragged, startPlacement_, dropped, true));
        viewport.update();
        return;
    }
    model::MergeSpec spec;
    spec.mode = candidate->mode;
    spec.draggedJoint = candidate->draggedJoint;
    spec.target = candidate->mode == MergeMode::Split ? model::JointChoice(candidate->targetPoint)
                                                      : model::JointChoice(candidate->targetJoint);
    QElapsedTimer timer;
    timer.start();
    try {
        auto merge = model::MergePartsCommand::create(document, dragged, candidate->target, spec);
        const QString summary = merge->summary();
        // The drop and the merge are one step: undo puts both parts back
        // where they were before the drag.
        document.undoStack()->beginMacro(merge->text());
        document.undoStack()->push(
            new model::MovePartCommand(document, dragged, startPlacement_, dropped, true));
        document.undoStack()->push(merge.release());
        document.undoStack()->endMacro();
        document.setSelection({candidate->target, kNoJoint});
        emit viewport.statusMessage(tr("%1 (%2 ms in all)").arg(summary).arg(timer.elapsed()));
    } catch (const Error& error) {
        document.setPlacement(dragged, startPlacement_);
        emit viewport.statusMessage(tr("Not merged: %1").arg(model::errorText(error)));
    }
    viewport.update();
}

void MergeTool::cancel(Viewport& viewport) {
    if (dragged_ && viewport.document()->contains(*dragged_)) {
        viewport.document()->setPlacement(*dragged_, startPlacement_);
        emit viewport.statusMessage(tr("Merge cancelled"));
    }
    dragged_.reset();
    candidate_.reset();
}

void MergeTool::addOverlay(const Viewport& viewport, ColouredVertices& lines) const {
    if (!candidate_ || !dragged_)
        return;
    const QVector3D lit(0.2f, 0.75f, 1.0f);
    const double size = 0.03 * worldBox(viewport.document()->part(*dragged_)).diagonal().norm();
    lines.add(toQt(candidate_->draggedPoint), lit);
    lines.add(toQt(candidate_->targetPoint), lit);
    addCross(lines, candidate_->draggedPoint, size, lit);
    addCross(lines, candidate_->targetPoint, size, lit);
}

}  // namespace rigmesh::widgets
