// Dragging a joint of a part with IK as the studio's pose tool does: from the
// part's current pose, keeping its pinned joints, with the pose tool's soft
// reach. Shared by the pose tool's recipe twin (the "pose" recipe step).
#pragma once

#include "model/PartNode.h"
#include "pose/InverseKinematics.h"

namespace rigmesh::model {

// How far up the skeleton a drag may turn joints (InverseKinematics.h):
// Limb stops below the nearest junction, so other limbs never move (the
// studio's default); Body goes up to the root (Alt + drag).
enum class IkReach { Limb, Body };

// The IK options of the pose tool (soft reach 0.05, see InverseKinematics.h).
IkOptions poseToolIkOptions(IkReach reach = IkReach::Limb);

// Drags `joint` of the node's skeleton toward `target` (in the part's own
// frame). Throws rigmesh::Error on a node without a part, an unknown joint
// or a non-finite target.
IkResult dragPartJoint(const PartNode& node, JointId joint, const Vec3& target,
                       IkReach reach = IkReach::Limb);

}  // namespace rigmesh::model
