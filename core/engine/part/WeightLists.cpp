#include "part/WeightLists.h"

#include <algorithm>

namespace rigmesh {

double weightOfBone(const WeightList& list, BoneId bone) {
    for (const auto& [b, w] : list)
        if (b == bone)
            return w;
    return 0.0;
}

LockedBones::LockedBones(const Skeleton& skeleton, const std::set<BoneId>& locked)
    : index_(skeleton), locked_(skeleton.boneCount(), 0) {
    for (BoneId id : locked)
        if (skeleton.hasBone(id))
            locked_[skeleton.indexOfBone(id)] = 1;
}

bool setWeightKeepingLocks(WeightList& list, BoneId bone, double target,
                           const LockedBones& locked) {
    double lockedSum = 0.0, freeSum = 0.0;
    for (const auto& [b, w] : list) {
        if (b == bone)
            continue;
        (locked.contains(b) ? lockedSum : freeSum) += w;
    }
    target = std::clamp(target, 0.0, std::max(0.0, 1.0 - lockedSum));
    const double freeTarget = 1.0 - lockedSum - target;
    if (freeSum <= 0.0 && (freeTarget > kDroppedWeight || target == weightOfBone(list, bone)))
        return false;  // nothing unlocked to hand the rest to, or to take it from
    // The list stays sorted by bone: scale in place, then put `bone` where
    // it belongs (no allocation unless the bone is new to the vertex).
    bool placed = false;
    for (auto& [b, w] : list) {
        if (b == bone) {
            w = target;
            placed = true;
        } else if (!locked.contains(b)) {
            w = freeSum > 0.0 ? w * freeTarget / freeSum : 0.0;
        }
    }
    if (!placed)
        list.insert(std::lower_bound(list.begin(), list.end(), std::make_pair(bone, 0.0)),
                    {bone, target});
    // By construction the weights sum to 1 up to rounding; locked ones stay.
    std::erase_if(list, [&](const auto& entry) {
        return !(entry.second > kDroppedWeight ||
                 (locked.contains(entry.first) && entry.second > 0.0));
    });
    return true;
}

bool setWeightHandingOn(WeightList& list, BoneId bone, double target, BoneId receiver,
                        const LockedBones& locked) {
    if (setWeightKeepingLocks(list, bone, target, locked))
        return true;
    double lockedSum = 0.0;
    for (const auto& [b, w] : list) {
        if (b == bone)
            continue;
        if (!locked.contains(b) && w > 0.0)
            return false;  // another unlocked bone was there: not a one-bone region
        lockedSum += locked.contains(b) ? w : 0.0;
    }
    target = std::clamp(target, 0.0, std::max(0.0, 1.0 - lockedSum));
    const double rest = 1.0 - lockedSum - target;
    if (rest <= kDroppedWeight || receiver == bone || locked.contains(receiver))
        return false;
    WeightList out;
    out.reserve(list.size() + 2);
    for (const auto& entry : list)
        if (entry.first != bone && entry.first != receiver &&
            (entry.second > kDroppedWeight || locked.contains(entry.first)))
            out.push_back(entry);
    if (target > kDroppedWeight)
        out.emplace_back(bone, target);
    out.emplace_back(receiver, rest);
    std::sort(out.begin(), out.end());
    list = std::move(out);
    return true;
}

bool normaliseKeepingLocks(WeightList& list, const LockedBones& locked) {
    double lockedSum = 0.0, freeSum = 0.0;
    for (const auto& [b, w] : list)
        (locked.contains(b) ? lockedSum : freeSum) += w;
    const double room = std::max(0.0, 1.0 - lockedSum);
    if (freeSum <= 0.0)
        return room <= kDroppedWeight;  // only locked weights: nothing to rescale
    WeightList out;
    out.reserve(list.size());
    for (const auto& [b, w] : list) {
        const double scaled = locked.contains(b) ? w : w * room / freeSum;
        if (scaled > kDroppedWeight || (locked.contains(b) && scaled > 0.0))
            out.emplace_back(b, scaled);
    }
    if (out.empty())
        return false;
    std::sort(out.begin(), out.end());
    list = std::move(out);
    return true;
}

}  // namespace rigmesh
