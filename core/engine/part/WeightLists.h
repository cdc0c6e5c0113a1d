// One vertex's skin weight list, (bone id, weight) sorted by bone id, as
// SkinWeightsById holds it: the edits painting and the clean-ups share, each
// keeping locked bones bit for bit.
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "part/BoneWeights.h"
#include "rig/Skeleton.h"

namespace rigmesh {

using WeightList = std::vector<std::pair<BoneId, double>>;

// Weights below this are dropped after an edit (far below the 1e-6 a sum
// may be off by).
inline constexpr double kDroppedWeight = 1e-9;

// The weight of `bone` in `list` (0 if absent).
double weightOfBone(const WeightList& list, BoneId bone);

// Which bones are locked, looked up per weight in the edits' inner loops
// without a tree search. Ids the skeleton does not have are never locked.
class LockedBones {
  public:
    LockedBones(const Skeleton& skeleton, const std::set<BoneId>& locked);
    bool contains(BoneId bone) const {
        const int index = index_[bone];
        return index >= 0 && locked_[index];
    }

  private:
    BoneIndexTable index_;
    std::vector<char> locked_;  // per position in the skeleton's bone list
};

// Sets `bone` to `target` (clamped to what the locked bones leave), the other
// unlocked bones scaled to take up the difference; locked weights are kept
// bit for bit. False, with `list` unchanged, if that cannot be done: no
// unlocked bone to hand the rest to or to take it from.
bool setWeightKeepingLocks(WeightList& list, BoneId bone, double target, const LockedBones& locked);

// As setWeightKeepingLocks, but where no other unlocked bone weighs the
// vertex (a region `bone` alone leads) the weight `bone` gives up goes to
// `receiver` (an unlocked bone other than `bone`), as Blender's
// auto-normalise hands it on. False, with `list` unchanged, if nothing
// changes: no weight to give up, or no room left by the locked bones.
bool setWeightHandingOn(WeightList& list, BoneId bone, double target, BoneId receiver,
                        const LockedBones& locked);

// Rescales the unlocked entries so the list sums to 1, dropping those below
// kDroppedWeight and keeping the locked ones bit for bit; the result is
// sorted by bone. False, with `list` unchanged, if the unlocked entries sum
// to nothing (or there are none) while the locked ones leave room.
bool normaliseKeepingLocks(WeightList& list, const LockedBones& locked);

}  // namespace rigmesh
