#include "model/MergeRigCarry.h"

#include <QCoreApplication>
#include <QStringList>
#include <algorithm>
#include <optional>

#include "model/PartClips.h"
#include "pose/PoseHierarchy.h"

namespace rigmesh::model {
namespace {

// Per joint: its parent (none for the root) and the joints below it: the
// bone ending at the joint, and what its rotation turns.
struct BoneShape {
    std::optional<JointId> head;
    std::set<JointId> below;
};

std::map<JointId, BoneShape> boneShapes(const Skeleton& skeleton) {
    std::map<JointId, BoneShape> shapes;
    if (skeleton.jointCount() == 0)
        return shapes;
    const PoseHierarchy hierarchy(skeleton);
    const std::vector<int>& order = hierarchy.parentFirstOrder();
    for (auto at = order.rbegin(); at != order.rend(); ++at) {
        BoneShape& shape = shapes[hierarchy.jointId(*at)];
        for (int child : hierarchy.children(*at)) {
            const JointId id = hierarchy.jointId(child);
            shapes[id].head = hierarchy.jointId(*at);
            shape.below.insert(id);
            const std::set<JointId>& further = shapes[id].below;
            shape.below.insert(further.begin(), further.end());
        }
    }
    return shapes;
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
    out.otherClips = merged.otherClips;

    // Dragged bones that are the same bone after the merge: the same head
    // and the same joints below.
    const auto before = boneShapes(dragged.part->skeleton);
    const auto after = boneShapes(merged.part->skeleton);
    auto mappedId = [&](JointId id) -> std::optional<JointId> {
        const auto m = draggedJoints.find(id);
        return m == draggedJoints.end() ? std::nullopt : std::optional<JointId>(m->second);
    };
    std::map<JointId, JointId> rotatable;  // dragged id -> merged id
    for (const auto& [joint, shape] : before) {
        const auto to = mappedId(joint);
        if (!to || !after.contains(*to) || !shape.head)
            continue;  // pruned, or the dragged root (its rotation turned the whole part)
        const BoneShape& now = after.at(*to);
        if (!now.head || mappedId(*shape.head) != now.head)
            continue;
        std::set<JointId> mapped;
        for (JointId id : shape.below)
            if (const auto m = mappedId(id))
                mapped.insert(*m);
        if (mapped == now.below)
            rotatable[joint] = *to;
    }

    // A dragged pose onto merged ids: the rotatable joints only (bit for bit
    // when both parts have the same axes).
    const bool sameAxes = isIdentity(draggedToMerged);
    std::set<JointId> kept, dropped;
    // The dragged root's rotation turned the whole dragged part about its
    // root; after the merge the root ends a bone of the merged skeleton, so
    // that rotation moves into the bones leaving the root (their world
    // rotation was the root's times their own, about the same point).
    const JointId draggedRoot = dragged.part->skeleton.root();
    std::vector<JointId> rootChildren;
    for (const auto& [joint, shape] : before)
        if (shape.head == draggedRoot)
            rootChildren.push_back(joint);
    auto turned = [&](const Eigen::Quaterniond& q) {
        return sameAxes ? q : (draggedToMerged * q * draggedToMerged.conjugate()).normalized();
    };
    // Returns whether any rotation was carried.
    auto carry = [&](const Pose& from, Pose& into) {
        bool any = false;
        const Eigen::Quaterniond rootTurn = from.rotation(draggedRoot);
        const bool rootTurned = !isIdentity(rootTurn);
        for (const auto& [joint, rotation] : from.rotations) {
            if (joint == draggedRoot || isIdentity(rotation))
                continue;
            if (rootTurned &&
                std::find(rootChildren.begin(), rootChildren.end(), joint) != rootChildren.end())
                continue;  // below, with the root's rotation
            if (const auto to = rotatable.find(joint); to != rotatable.end()) {
                into.rotations[to->second] = turned(rotation);
                kept.insert(joint);
                any = true;
            } else {
                dropped.insert(joint);
            }
        }
        if (rootTurned) {
            for (JointId child : rootChildren) {
                const Eigen::Quaterniond own = from.rotation(child);
                const auto to = rotatable.find(child);
                if (to == rotatable.end()) {
                    dropped.insert(draggedRoot);
                    if (!isIdentity(own))
                        dropped.insert(child);
                    continue;
                }
                into.rotations[to->second] = turned((rootTurn * own).normalized());
                kept.insert(draggedRoot);
                if (!isIdentity(own))
                    kept.insert(child);
                any = true;
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

    // Keys at the union of both clips' key times, each clip evaluated there:
    // every existing key of either part keeps its exact pose. Keys none of
    // whose rotations survive add nothing (not even their times). Returns
    // whether `into` changed.
    auto mergeClip = [&](const Clip* ours, const Clip& theirs, Clip& into) {
        if (theirs.keys().empty())
            return false;
        const bool targetKeyed = ours && !ours->keys().empty();
        const Clip& settings = targetKeyed ? *ours : theirs;
        Clip clip = emptiedClip(settings);
        clip.name = ours ? ours->name : theirs.name;
        std::vector<double> times = targetKeyed ? ours->keyTimes() : std::vector<double>();
        for (double time : theirs.keyTimes())
            if (!targetKeyed || !ours->hasKey(time))
                times.push_back(time);
        for (double time : times) {
            Pose key = targetKeyed ? ours->evaluate(time) : Pose();
            carry(theirs.evaluate(time), key);
            clip.insertExactKey(time, key);
        }
        int keys = 0;
        for (const auto& [time, key] : theirs.keys()) {
            Pose scratch;
            keys += carry(key, scratch) ? 1 : 0;
        }
        if (keys == 0)
            return false;
        out.mergedKeys += keys;
        out.clipSettingsDiffered =
            out.clipSettingsDiffered ||
            (targetKeyed &&
             (ours->framesPerSecond() != theirs.framesPerSecond() ||
              ours->interpolation != theirs.interpolation || ours->mode != theirs.mode));
        into = std::move(clip);
        return true;
    };
    // The active clips into each other; every other dragged clip into the
    // merged clip of its name, or as a new clip.
    mergeClip(&merged.clip, dragged.clip, out.clip);
    for (const Clip& theirs : dragged.otherClips) {
        const std::string name = clipName(theirs);
        Clip* ours = name == clipName(out.clip) ? &out.clip : nullptr;
        for (Clip& other : out.otherClips)
            if (clipName(other) == name)
                ours = &other;
        if (ours) {
            const Clip target = *ours;
            mergeClip(&target, theirs, *ours);
        } else if (Clip added = emptiedClip(theirs); mergeClip(nullptr, theirs, added)) {
            out.otherClips.push_back(std::move(added));
        }
    }
    out.otherClips = sortedByName(std::move(out.otherClips));
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
        keptParts << tr("the rotations of %n joint(s)", nullptr,
                        static_cast<int>(keptRotations.size()));
    if (!keptPins.empty())
        keptParts << tr("%n pin(s)", nullptr, static_cast<int>(keptPins.size()));
    if (mergedKeys > 0)
        keptParts << tr("%n key(s)", nullptr, mergedKeys);
    if (!droppedRotations.empty())
        droppedParts << tr("the rotations of joint(s) %1 (in the merged skeleton they would turn "
                           "other bones)",
                           nullptr, static_cast<int>(droppedRotations.size()))
                            .arg(jointList(droppedRotations));
    if (!droppedPins.empty())
        droppedParts << tr("the pin(s) of joint(s) %1 (pruned)", nullptr,
                           static_cast<int>(droppedPins.size()))
                            .arg(jointList(droppedPins));
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
