// What of the dragged part's pose, pins and keyed clip a merge keeps (paper
// 3.2: keep what maps onto surviving bones and say what was
// dropped). The merge gives the dragged part's joints new ids
// (MergeResult::draggedJoints, absent for pruned joints). A pose holds one
// rotation per bone, keyed by the joint the bone ends at (pose/Pose.h), so a
// dragged rotation is kept, on its new id, when its bone is still the same
// bone: the same head joint, and below it exactly the same joints. That is
// not so on the way from the dragged root to where the parts meet (there the
// bones now hang the other way), at a joint shared with the target's own
// bones. The dragged root's whole-part rotation moves into the bones leaving
// the root (their world rotation is the root's times their own, about the
// same point). Pins are kept on
// every surviving joint. Keys are merged clip by clip, a dragged clip into
// the merged clip of the same name (the active clips into each other; a
// name the merged part lacks becomes a new clip), at the union of both
// clips' key times: each key is the target's clip there and the dragged
// part's clip there (evaluated, so neither animation changes at its own
// keys). The dragged part's root offset cannot move the merged root and is
// dropped.
#pragma once

#include <map>
#include <set>
#include <vector>

#include <QCoreApplication>
#include <QString>

#include "model/PartNode.h"
#include "pose/Clip.h"
#include "pose/Pose.h"

namespace rigmesh::model {

struct DraggedRigCarry {
    Q_DECLARE_TR_FUNCTIONS(DraggedRigCarry)

  public:
    rigmesh::Pose pose;                     // the merged node's pose
    std::set<rigmesh::JointId> pinned;      // the merged node's pins
    rigmesh::Clip clip = rigmesh::Clip();   // the merged node's clip
    std::vector<rigmesh::Clip> otherClips;  // the merged node's other clips, sorted by name
    // In the dragged part's joint ids.
    std::vector<rigmesh::JointId> keptRotations;     // posed or keyed, kept
    std::vector<rigmesh::JointId> droppedRotations;  // posed or keyed, dropped
    std::vector<rigmesh::JointId> keptPins, droppedPins;
    int mergedKeys = 0;                 // dragged key times now in the clips
    bool droppedRootOffset = false;     // the dragged pose or keys moved its root
    bool clipSettingsDiffered = false;  // fps, interpolation or playback: the target's
    // For the user, "" when the dragged part had nothing to carry: what was
    // kept and precisely what was dropped.
    QString describe(const QString& draggedName) const;
};

// `merged`: the target's node after the merge (editedNode: its own pose, pins
// and clip already carried onto the merged skeleton). `dragged`: the dragged
// part's node as it was. `draggedJoints`: dragged joint id -> merged id.
// `draggedToMerged`: the rotation from the dragged part's axes to the merged
// part's (their placements differ); bone rotations are about the part's
// axes at rest, so each is turned by it (R q R^-1).
DraggedRigCarry carryDraggedRig(const PartNode& merged, const PartNode& dragged,
                                const std::map<rigmesh::JointId, rigmesh::JointId>& draggedJoints,
                                const Eigen::Quaterniond& draggedToMerged);

}  // namespace rigmesh::model
