// What of a part's pose, pins and keyed clip survives a rebuild of its
// skeleton (other edge length or smoothing): the entries of the joints the
// new skeleton still has, the same id at about the same place (within a
// quarter of the old skeleton's mean bone length). The rest are dropped and
// counted, so the user can be told.
#pragma once

#include <set>

#include "pose/Clip.h"
#include "pose/Pose.h"
#include "rig/Skeleton.h"

namespace rigmesh::model {

struct CarriedRig {
    rigmesh::Pose pose;
    std::set<rigmesh::JointId> pinned;
    rigmesh::Clip clip = rigmesh::Clip();
    int keptJoints = 0;     // posed, pinned or keyed joints kept
    int droppedJoints = 0;  // posed, pinned or keyed joints the new skeleton lacks
};

CarriedRig carryRigOver(const rigmesh::Skeleton& from, const rigmesh::Skeleton& to,
                        const rigmesh::Pose& pose, const std::set<rigmesh::JointId>& pinned,
                        const rigmesh::Clip& clip);

}  // namespace rigmesh::model
