// One vertex's skin weight list, (bone index, weight) sorted by bone, as
// SkinWeights holds it: the edits painting and the clean-ups share, each
// keeping locked bones bit for bit (issue 14 item 3).
#pragma once

#include <set>
#include <utility>
#include <vector>

#include "rig/Skeleton.h"

namespace rigmesh {

using WeightList = std::vector<std::pair<int, double>>;

// Weights below this are dropped after an edit (far below the 1e-6 a sum
// may be off by).
inline constexpr double kDroppedWeight = 1e-9;

// The weight of bone index `bone` in `list` (0 if absent).
double weightOfIndex(const WeightList& list, int bone);

// Per bone index of `skeleton`: 1 if the bone is in `locked`. Ids the
// skeleton does not have are ignored.
std::vector<char> lockedBoneIndices(const Skeleton& skeleton, const std::set<BoneId>& locked);

// Sets `bone` to `target` (clamped to what the locked bones leave), the other
// unlocked bones scaled to take up the difference; locked weights are kept
// bit for bit. False, with `list` unchanged, if that cannot be done: no
// unlocked bone to hand the rest to or to take it from.
bool setWeightKeepingLocks(WeightList& list, int bone, double target,
                           const std::vector<char>& lockedIndex);

// Rescales the unlocked entries so the list sums to 1, dropping those below
// kDroppedWeight and keeping the locked ones bit for bit; the result is
// sorted by bone. False, with `list` unchanged, if the unlocked entries sum
// to nothing (or there are none) while the locked ones leave room.
bool normaliseKeepingLocks(WeightList& list, const std::vector<char>& lockedIndex);

}  // namespace rigmesh
