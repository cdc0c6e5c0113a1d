// Skeleton refinement (paper 3.3) with the rig kept: splitting a bone adds a
// joint, deleting one collapses it to its midpoint. The paper treats both as
// cuts followed by a merge back; the surface comes back as it was, so here
// the surface is left untouched (every vertex bit for bit) and only the
// re-skin of that merge runs (3.2.2): seeded at the cut loop for a split,
// with every vertex of the collapsed piece included for a delete.
#pragma once

#include <vector>

#include "part/Part.h"

namespace rigmesh {

struct BoneEditResult {
    Part part;
    std::vector<int> reskinned;  // vertices whose weights were solved again
    int bonesInvolved = 0;
    JointId newJoint = kNoJoint;  // split: the joint added
    double milliseconds = 0.0;
};

// Splits `bone` at the point of it nearest to `at`. Throws Error (nothing
// changes) for an unknown bone or a point within 5% of the bone's length of
// either end.
BoneEditResult splitBoneAt(const Part& part, BoneId bone, const Vec3& at);

// Deletes `bone`: its two joints merge at its midpoint. Throws Error for an
// unknown bone or the part's only bone.
BoneEditResult deleteBone(const Part& part, BoneId bone);

// The bone of `part` nearest to a point (its own coordinates).
BoneId nearestBone(const Part& part, const Vec3& point);

}  // namespace rigmesh
