#include "model/MergeRigCarry.h"

#include <QCoreApplication>
#include <QStringList>

#include "pose/PoseHierarchy.h"

namespace rigmesh::model {
namespace {

QString tr(const char* text, int n = -1) {
    return QCoreApplication::translate("DraggedRigCarry", text, nullptr, n);
}

// Per joint: the joints its rotation turns (its descendants from the root).
std::map<JointId, std::set<JointId>> turnedJoints(const Skeleton& skeleton) {
    std::map<JointId, std::set<JointId>> turned;
    if (skeleton.jointCount() == 0)
        return turned;
    const PoseHierarchy hierarchy(skeleton);
    const std::vector<int>& order = hierarchy.parentFirstOrder();
    for (auto at = order.rbegin(); at != order.rend(); ++at) {
        std::set<JointId>& below = turned[hierarchy.jointId(*at)];
        for (int child : hierarchy.children(*at)) {
            const JointId id = hierarchy.jointId(child);
            below.insert(id);
            const std::set<JointId>& further = turned[id];
            below.insert(further.begin(), further.end());
        }
    }
    return turned;
}

bool isIdentity(const Eigen::Quaterniond& q) {
    return q.vec().isZero(0.0) && std::abs(q.w()) == 1.0;
}

QString jointList(const std::vector<JointId>& joints) {
    QStringList ids;
    for (JointId id : joints)
        ids << QString::number(id);
    return ids.join(QStringLiteral(", "));
}

}  // namespace

DraggedRigCarry carryDraggedRig(const PartNode& merged, const PartNode& dragged,
                                const std::map<JointId, JointId>& draggedJoints,
                                const Eigen::Quaterniond& draggedToMerged) {
    DraggedRigCarry out;
    out.pose = merged.pose;
    out.pinned = merged.pinnedJoints;
    out.clip = merged.clip;

    // Dragged joints whose rotation turns the same joints after the merge.
    const auto before = turnedJoints(dragged.part->skeleton);
    const auto after = turnedJoints(merged.part->skeleton);
    std::map<JointId, JointId> rotatable;  // dragged id -> merged id
    for (const auto& [joint, below] : before) {
        const auto to = draggedJoints.find(joint);
        if (to == draggedJoints.end() || !after.contains(to->second))
            continue;
        std::set<JointId> mapped;
        for (JointId id : below)
            if (const auto m = draggedJoints.find(id); m != draggedJoints.end())
                mapped.insert(m->second);
        if (mapped == after.at(to->second))
            rotatable[joint] = to->second;
    }

    // A dragged pose onto merged ids: the rotatable joints only (bit for bit
    // when both parts have the same axes).
    const bool sameAxes = isIdentity(draggedToMerged);
    std::set<JointId> kept, dropped;
    // Returns whether any rotation was carried.
    auto carry = [&](const Pose& from, Pose& into) {
        bool any = false;
        for (const auto& [joint, rotation] : from.rotations) {
            if (isIdentity(rotation))
                continue;
            if (const auto to = rotatable.find(joint); to != rotatable.end()) {
                into.rotations[to->second] =
                    sameAxes
                        ? rotation
                        : (draggedToMerged * rotation * draggedToMerged.conjugate()).normalized();
                kept.insert(joint);
                any = true;
            } else {
                dropped.insert(joint);
            }
        }
        out.droppedRootOffset = out.droppedRootOffset || !from.rootTranslation.isZero(0.0);
        return any;
    };
    carry(dragged.pose, out.pose);

    for (JointId joint : dragged.pinnedJoints) {
        if (const auto to = draggedJoints.find(joint); to != draggedJoints.end()) {
            out.pinned.insert(to->second);
            out.keptPins.push_back(joint);
        } else {
            out.droppedPins.push_back(joint);
        }
    }

    // Keys at the union of both parts' key times, each part's clip evaluated
    // there: every existing key of either part keeps its exact pose. Keys
    // none of whose rotations survive add nothing (not even their times).
    const Clip& theirs = dragged.clip;
    if (!theirs.keys().empty()) {
        const Clip& ours = merged.clip;
        const bool targetKeyed = !ours.keys().empty();
        const Clip& settings = targetKeyed ? ours : theirs;
        Clip clip = emptiedClip(settings);
        clip.name = settings.name;
        out.clipSettingsDiffered =
            targetKeyed && (ours.framesPerSecond() != theirs.framesPerSecond() ||
                            ours.interpolation != theirs.interpolation || ours.mode != theirs.mode);
        std::vector<double> times = ours.keyTimes();
        for (double time : theirs.keyTimes())
            if (!ours.hasKey(time))
                times.push_back(time);
        for (double time : times) {
            Pose key = targetKeyed ? ours.evaluate(time) : Pose();
            carry(theirs.evaluate(time), key);
            clip.insertExactKey(time, key);
        }
        for (const auto& [time, key] : theirs.keys()) {
            Pose scratch;
            out.mergedKeys += carry(key, scratch) ? 1 : 0;
        }
        if (out.mergedKeys > 0)
            out.clip = std::move(clip);
        else
            out.clipSettingsDiffered = false;
    }
    for (JointId joint : dropped)
        if (!kept.contains(joint))
            out.droppedRotations.push_back(joint);
    out.keptRotations.assign(kept.begin(), kept.end());
    // A joint kept at one key and not at another cannot happen: whether a
    // joint is rotatable depends on the skeletons only.
    return out;
}

QString DraggedRigCarry::describe(const QString& draggedName) const {
    QStringList keptParts, droppedParts;
    if (!keptRotations.empty())
        keptParts << tr("the rotations of %n joint(s)", static_cast<int>(keptRotations.size()));
    if (!keptPins.empty())
        keptParts << tr("%n pin(s)", static_cast<int>(keptPins.size()));
    if (mergedKeys > 0)
        keptParts << tr("%n key(s)", mergedKeys);
    if (!droppedRotations.empty())
        droppedParts << tr("the rotations of joint(s) %1 (in the merged skeleton they would turn "
                           "other bones)")
                            .arg(jointList(droppedRotations));
    if (!droppedPins.empty())
        droppedParts << tr("the pin(s) of joint(s) %1 (pruned)").arg(jointList(droppedPins));
    if (droppedRootOffset)
        droppedParts << tr("its root offset");
    if (keptParts.isEmpty() && droppedParts.isEmpty())
        return {};
    QString text = tr("from %1: ").arg(draggedName);
    if (!keptParts.isEmpty())
        text += tr("kept %1").arg(keptParts.join(QStringLiteral(", ")));
    if (!droppedParts.isEmpty())
        text += (keptParts.isEmpty() ? QString() : QStringLiteral("; ")) +
                tr("dropped %1").arg(droppedParts.join(QStringLiteral(", ")));
    if (clipSettingsDiffered)
        text += tr("; its keys now play at the target's frame rate and interpolation");
    return text;
}

}  // namespace rigmesh::model
