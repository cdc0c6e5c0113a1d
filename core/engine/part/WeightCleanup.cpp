#include "part/WeightCleanup.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "base/Error.h"
#include "mesh/MeshAdjacency.h"
#include "part/WeightLists.h"
#include "rig/LocalBoneHeat.h"

namespace rigmesh {

namespace {

// Keeps the unlocked entries `keep` says yes to (always the largest
// unlocked one; `rank` counts every kept entry before it, locked ones
// first), renormalised through the unlocked ones.
template <typename Keep>
int filterWeights(Part& part, const std::set<BoneId>& locked, Keep&& keep) {
    const LockedBones lockedBones(part.skeleton, locked);
    int changed = 0;
    for (auto& list : part.weights.perVertex) {
        if (list.empty())
            continue;
        WeightList kept, unlocked;
        for (const auto& entry : list)
            (lockedBones.contains(entry.first) ? kept : unlocked).push_back(entry);
        std::stable_sort(unlocked.begin(), unlocked.end(),
                         [](const auto& a, const auto& b) { return a.second > b.second; });
        for (std::size_t i = 0; i < unlocked.size(); ++i)
            if (i == 0 || keep(unlocked[i], kept.size()))
                kept.push_back(unlocked[i]);
        std::sort(kept.begin(), kept.end());
        double sum = 0.0;
        for (const auto& entry : kept)
            sum += entry.second;
        if (kept.size() == list.size() && std::abs(sum - 1.0) <= 1e-12)
            continue;  // already as asked: left bit for bit
        if (!normaliseKeepingLocks(kept, lockedBones))
            continue;
        if (kept != list) {
            list = std::move(kept);
            ++changed;
        }
    }
    return changed;
}

}  // namespace

int normalizeAllWeights(Part& part, const std::set<BoneId>& locked) {
    return filterWeights(part, locked, [](const auto&, std::size_t) { return true; });
}

int cleanWeights(Part& part, double threshold, const std::set<BoneId>& locked) {
    if (!(threshold >= 0.0) || !(threshold < 1.0))
        throw Error(MessageId::CleanThresholdOutOfRange);
    return filterWeights(part, locked,
                         [&](const auto& entry, std::size_t) { return entry.second >= threshold; });
}

int limitWeightInfluences(Part& part, int influences, const std::set<BoneId>& locked) {
    if (influences < 1)
        throw Error(MessageId::LimitNeedsOneInfluence);
    return filterWeights(part, locked, [&](const auto&, std::size_t keptSoFar) {
        return static_cast<int>(keptSoFar) < influences;
    });
}

int smoothAllWeights(Part& part, const SmoothAllOptions& options, const std::set<BoneId>& locked) {
    if (!(options.factor >= 0.0) || !(options.factor <= 1.0) || options.iterations < 1 ||
        options.iterations > 100)
        throw Error(MessageId::SmoothAllOutOfRange);
    const LockedBones lockedBones(part.skeleton, locked);
    const std::vector<std::vector<int>> neighbours = vertexNeighbours(part.mesh);
    auto& weights = part.weights.perVertex;
    const std::vector<WeightList> original = weights;
    for (int pass = 0; pass < options.iterations; ++pass) {
        const std::vector<WeightList> previous = weights;
        for (std::size_t v = 0; v < weights.size(); ++v) {
            const WeightList& own = previous[v];
            // Nothing to smooth where every bone is locked.
            if (std::all_of(own.begin(), own.end(),
                            [&](const auto& entry) { return lockedBones.contains(entry.first); }))
                continue;
            std::map<BoneId, double> mixed;
            for (const auto& [b, w] : own)
                mixed[b] = lockedBones.contains(b) ? w : (1.0 - options.factor) * w;
            const double share =
                neighbours[v].empty() ? 0.0 : options.factor / double(neighbours[v].size());
            if (neighbours[v].empty())
                for (const auto& [b, w] : own)
                    mixed[b] = w;
            for (int n : neighbours[v])
                for (const auto& [b, w] : previous[n])
                    if (!lockedBones.contains(b))
                        mixed[b] += share * w;
            WeightList smoothed(mixed.begin(), mixed.end());
            if (normaliseKeepingLocks(smoothed, lockedBones))
                weights[v] = std::move(smoothed);
        }
    }
    int changed = 0;
    for (std::size_t v = 0; v < weights.size(); ++v)
        changed += weights[v] != original[v];
    return changed;
}

int recomputeWeights(Part& part, const std::set<BoneId>& locked) {
    if (part.skeleton.boneCount() == 0)
        throw Error(MessageId::RecomputeNeedsSkeleton);
    const LockedBones lockedBones(part.skeleton, locked);
    const WeightsById fresh = recomputeWeightsGlobally(part.mesh, part.skeleton);
    auto& weights = part.weights.perVertex;
    int changed = 0;
    for (std::size_t v = 0; v < weights.size() && v < fresh.size(); ++v) {
        WeightList list;
        for (const auto& entry : weights[v])
            if (lockedBones.contains(entry.first))
                list.push_back(entry);
        for (const auto& entry : fresh[v])
            if (!lockedBones.contains(entry.first))
                list.push_back(entry);
        std::sort(list.begin(), list.end());
        if (!normaliseKeepingLocks(list, lockedBones) || list == weights[v])
            continue;
        weights[v] = std::move(list);
        ++changed;
    }
    return changed;
}

}  // namespace rigmesh
