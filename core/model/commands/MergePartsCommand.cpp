#include "model/commands/MergePartsCommand.h"

#include <algorithm>

#include <nlohmann/json.hpp>

#include "base/Error.h"
#include "model/MergeRigCarry.h"
#include "model/RigCarryOver.h"
#include "model/recipe/RecipeJson.h"

namespace rigmesh::model {

namespace {

// The part as seen from `frame`: its vertices and joints moved from its own
// placement into the frame's coordinates.
Part inFrameOf(const Part& part, const Placement& own, const Placement& frame) {
    Part moved = part;
    for (Vec3& p : moved.mesh.vertices)
        p = frame.toLocal(own.toWorld(p));
    for (const Joint& joint : std::vector<Joint>(moved.skeleton.joints()))
        moved.skeleton.setJointPosition(joint.id, frame.toLocal(own.toWorld(joint.position)));
    return moved;
}

JointId nearestJoint(const Skeleton& skeleton, const Vec3& point) {
    JointId best = kNoJoint;
    double bestDistance = 0.0;
    for (const Joint& joint : skeleton.joints()) {
        const double d = (joint.position - point).squaredNorm();
        if (best == kNoJoint || d < bestDistance) {
            best = joint.id;
            bestDistance = d;
        }
    }
    return best;
}

BoneId nearestBone(const Part& part, const Vec3& point) {
    const std::vector<BoneSegment> segments = part.boneSegments();
    int best = 0;
    for (int b = 1; b < static_cast<int>(segments.size()); ++b)
        if (pointSegmentDistance(point, segments[b]) < pointSegmentDistance(point, segments[best]))
            best = b;
    return part.skeleton.bones()[best].id;
}

// A joint choice of a part (given in the part's own frame as `part`, placed
// at `placement`) as an id; throws if the id is unknown.
JointId resolveJoint(const JointChoice& choice, const Part& part, const Placement& placement,
                     const QString& partName) {
    if (const auto* id = std::get_if<JointId>(&choice)) {
        if (!part.skeleton.hasJoint(*id))
            throw Error(MessageId::NamedPartHasNoJoint, partName.toStdString(), *id);
        return *id;
    }
    return nearestJoint(part.skeleton, placement.toLocal(std::get<Vec3>(choice)));
}

}  // namespace

std::unique_ptr<MergePartsCommand> MergePartsCommand::create(Document& document, PartId dragged,
                                                             PartId target, const MergeSpec& spec) {
    if (dragged == target)
        throw Error(MessageId::MergeIntoItself);
    return fromComputed(document, dragged, target,
                        compute(document.part(dragged), document.part(target), spec));
}

ComputedMerge MergePartsCommand::compute(const PartNode& from, const PartNode& into,
                                         const MergeSpec& spec) {
    if (!from.part || !into.part || from.part->skeleton.boneCount() == 0 ||
        into.part->skeleton.boneCount() == 0)
        throw Error(MessageId::MergeNeedsRiggedParts);

    const Part draggedPart = inFrameOf(*from.part, from.placement, into.placement);
    MergeSpec resolved = spec;
    MergeRequest request;
    request.join.mode = spec.mode;
    // The dragged joint is chosen in document coordinates, i.e. in its own
    // placement (the frame change keeps joint ids).
    request.join.draggedJoint =
        resolveJoint(spec.draggedJoint, *from.part, from.placement, from.name);
    resolved.draggedJoint = request.join.draggedJoint;
    if (spec.mode == MergeMode::Split) {
        const Vec3 point =
            std::holds_alternative<Vec3>(spec.target)
                ? into.placement.toLocal(std::get<Vec3>(spec.target))
                : into.part->skeleton
                      .joint(resolveJoint(spec.target, *into.part, into.placement, into.name))
                      .position;
        request.join.targetBone = nearestBone(*into.part, point);
        request.join.splitPoint = point;
        resolved.target = into.placement.toWorld(point);
    } else {
        request.join.targetJoint = resolveJoint(spec.target, *into.part, into.placement, into.name);
        resolved.target = request.join.targetJoint;
    }
    request.reskin = spec.reskin;
    request.compareGlobal = spec.compareGlobal;
    request.edgeLength = into.options.targetEdgeLength;
    return {resolved, mergeParts(*into.part, draggedPart, request)};
}

std::unique_ptr<MergePartsCommand> MergePartsCommand::fromComputed(Document& document,
                                                                   PartId dragged, PartId target,
                                                                   ComputedMerge computed) {
    if (dragged == target || !document.contains(dragged) || !document.contains(target))
        throw Error(MessageId::MergePartsGone);
    return std::unique_ptr<MergePartsCommand>(new MergePartsCommand(
        document, dragged, target, computed.resolved, std::move(computed.result)));
}

MergePartsCommand::MergePartsCommand(Document& document, PartId dragged, PartId target,
                                     const MergeSpec& spec, MergeResult result)
    : document_(document),
      draggedId_(dragged),
      targetId_(target),
      draggedIndex_(document.indexOf(dragged)),
      targetIndex_(document.indexOf(target)),
      spec_(spec),
      draggedNode_(document.part(dragged)),
      targetNode_(document.part(target)),
      stats_(result.stats) {
    mergedNode_ = editedNode(targetNode_, std::make_shared<const Part>(std::move(result.part)),
                             &droppedJoints_);
    // The dragged part's pose, pins and keys on their merged joint ids.
    const DraggedRigCarry carried = carryDraggedRig(
        mergedNode_, draggedNode_, result.draggedJoints,
        targetNode_.placement.rotation.conjugate() * draggedNode_.placement.rotation);
    mergedNode_.pose = carried.pose;
    mergedNode_.pinnedJoints = carried.pinned;
    mergedNode_.clip = carried.clip;
    mergedNode_.otherClips = carried.otherClips;
    draggedCarry_ = carried.describe(draggedNode_.name);
    setText(tr("Merge %1 into %2").arg(draggedNode_.name, targetNode_.name));
}

QString MergePartsCommand::summary() const {
    QString text = tr("merged in %1 ms: %2 vertices, %3 bones; %4 vertices and %5 bones re-skinned")
                       .arg(stats_.totalMs, 0, 'f', 0)
                       .arg(stats_.vertices)
                       .arg(stats_.bones)
                       .arg(stats_.verticesInvolved)
                       .arg(stats_.bonesInvolved);
    if (stats_.prunedBones > 0)
        text += tr("; %n bone(s) pruned", nullptr, stats_.prunedBones);
    if (droppedJoints_ > 0)
        text +=
            tr("; %1 lost the pose, pins and keys of %n pruned joint(s)", nullptr, droppedJoints_)
                .arg(targetNode_.name);
    if (!draggedCarry_.isEmpty())
        text += QStringLiteral("; ") + draggedCarry_;
    return text;
}

void MergePartsCommand::redo() {
    document_.removePart(draggedId_);
    document_.replaceNode(targetId_, mergedNode_);
}

void MergePartsCommand::undo() {
    document_.replaceNode(targetId_, targetNode_);
    // The target is back at its index once the dragged part is.
    document_.insertPart(draggedIndex_, draggedNode_);
}

nlohmann::json MergePartsCommand::recipeStep() const {
    auto choice = [](const JointChoice& c) -> nlohmann::json {
        if (const auto* id = std::get_if<JointId>(&c))
            return *id;
        const Vec3& p = std::get<Vec3>(c);
        return {p.x(), p.y(), p.z()};
    };
    const char* mode = spec_.mode == MergeMode::Snap    ? "snap"
                       : spec_.mode == MergeMode::Split ? "split"
                                                        : "connect";
    return {{"command", "merge"},
            {"part", draggedIndex_},
            {"into", targetIndex_},
            {"mode", mode},
            {"joint", choice(spec_.draggedJoint)},
            {"target", choice(spec_.target)},
            {"reskin", spec_.reskin == Reskin::Local ? "local" : "global"}};
}

}  // namespace rigmesh::model
