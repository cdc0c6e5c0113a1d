// What of a part's pose, pins and keyed clip survives a rebuild of its
// skeleton (other edge length or smoothing): the entries of the joints the
// new skeleton still has, the same id at about the same place (within a
// quarter of the old skeleton's mean bone length). The rest are dropped and
// counted, so the user can be told.
#pragma once

#include <memory>
#include <set>
#include <vector>

#include "part/Part.h"
#include "pose/Clip.h"
#include "pose/Pose.h"
#include "rig/Skeleton.h"

namespace rigmesh::model {

struct CarriedRig {
    rigmesh::Pose pose;
    std::set<rigmesh::JointId> pinned;
    rigmesh::Clip clip = rigmesh::Clip();
    std::vector<rigmesh::Clip> otherClips;  // the part's other named clips, filtered alike
    int keptJoints = 0;                     // posed, pinned or keyed joints kept
    int droppedJoints = 0;                  // posed, pinned or keyed joints the new skeleton lacks
};

CarriedRig carryRigOver(const rigmesh::Skeleton& from, const rigmesh::Skeleton& to,
                        const rigmesh::Pose& pose, const std::set<rigmesh::JointId>& pinned,
                        const rigmesh::Clip& clip,
                        const std::vector<rigmesh::Clip>& otherClips = {});

struct PartNode;

// A node whose part a topology edit replaced (merge, cut, bone edits): a copy
// of `from` with `part` in its place, no stroke (it is no longer one sketch,
// so it cannot be rebuilt) and the pose, pins and keys `from` had for the
// joints the new skeleton keeps. `droppedJoints` (if given) gets the count
// of those it could not keep.
PartNode editedNode(const PartNode& from, std::shared_ptr<const Part> part,
                    int* droppedJoints = nullptr);

}  // namespace rigmesh::model
