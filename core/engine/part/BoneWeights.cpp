#include "part/BoneWeights.h"

#include <algorithm>

#include "base/Error.h"

namespace rigmesh {

namespace {

template <typename Id>
std::vector<std::vector<std::pair<BoneId, double>>> listsById(
    const Skeleton& skeleton, const std::vector<std::vector<std::pair<Id, double>>>& lists) {
    std::vector<std::vector<std::pair<BoneId, double>>> result(lists.size());
    for (std::size_t v = 0; v < lists.size(); ++v) {
        for (const auto& [bone, value] : lists[v])
            result[v].emplace_back(skeleton.bones()[bone].id, value);
        std::sort(result[v].begin(), result[v].end());
    }
    return result;
}

// Ids below this many per bone (plus a margin) go in the plain array.
constexpr BoneId kDenseIdsPerBone = 4;
constexpr BoneId kDenseIdMargin = 64;

}  // namespace

SkinWeightsById weightsById(const Skeleton& skeleton, const SkinWeights& weights) {
    SkinWeightsById result;
    result.perVertex = listsById(skeleton, weights.perVertex);
    for (int bone : weights.failedBones)
        result.failedBones.push_back(skeleton.bones()[bone].id);
    result.warnings = weights.warnings;
    return result;
}

SkinWeights weightsByIndex(const Skeleton& skeleton, const SkinWeightsById& weights) {
    const BoneIndexTable index(skeleton);
    auto indexOf = [&](BoneId bone) {
        const int at = index[bone];
        if (at < 0)
            throw Error(MessageId::WeightNamesMissingBone, bone);
        return at;
    };
    SkinWeights result;
    result.perVertex.resize(weights.perVertex.size());
    for (std::size_t v = 0; v < weights.perVertex.size(); ++v) {
        auto& list = result.perVertex[v];
        list.reserve(weights.perVertex[v].size());
        for (const auto& [bone, w] : weights.perVertex[v])
            list.emplace_back(indexOf(bone), w);
        std::sort(list.begin(), list.end());
    }
    for (BoneId bone : weights.failedBones)
        result.failedBones.push_back(indexOf(bone));
    result.warnings = weights.warnings;
    return result;
}

ClosestBonesById closestById(const Skeleton& skeleton, const ClosestBones& closest) {
    return listsById(skeleton, closest);
}

ClosestBones closestByIndex(const Skeleton& skeleton, const ClosestBonesById& closest) {
    ClosestBones result(closest.size());
    for (std::size_t v = 0; v < closest.size(); ++v)
        for (const auto& [bone, d] : closest[v])
            if (skeleton.hasBone(bone))
                result[v].emplace_back(skeleton.indexOfBone(bone), d);
    return result;
}

BoneIndexTable::BoneIndexTable(const Skeleton& skeleton) {
    const auto bones = static_cast<BoneId>(skeleton.boneCount());
    const BoneId denseLimit = kDenseIdsPerBone * bones + kDenseIdMargin;
    BoneId largest = 0;
    for (const Bone& bone : skeleton.bones())
        largest = std::max(largest, bone.id);
    dense_.assign(bones > 0 ? std::min(largest, denseLimit - 1) + 1 : 0, -1);
    for (int b = 0; b < skeleton.boneCount(); ++b) {
        const BoneId id = skeleton.bones()[b].id;
        if (id < dense_.size())
            dense_[id] = b;
        else
            sparse_[id] = b;
    }
}

BoneId leadingBone(const std::vector<std::pair<BoneId, double>>& weights) {
    return std::max_element(weights.begin(), weights.end(),
                            [](const auto& a, const auto& b) { return a.second < b.second; })
        ->first;
}

std::map<BoneId, int> leadingVertexCounts(const WeightsById& weights) {
    std::map<BoneId, int> counts;
    for (const auto& list : weights)
        if (!list.empty())
            ++counts[leadingBone(list)];
    return counts;
}

void normaliseWeights(std::vector<std::pair<BoneId, double>>& weights) {
    // In place, with what a std::map<BoneId, double> summing the positive
    // weights would give (each bone's weights added in the order given, the
    // bones ascending), without its allocation per entry (per-vertex weight
    // lists in a cut, perf on bench_merge): the lists are a few bones long,
    // so a stable insertion sort.
    std::size_t kept = 0;
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (weights[i].second > 0.0)
            weights[kept++] = weights[i];
    for (std::size_t i = 1; i < kept; ++i) {
        const std::pair<BoneId, double> entry = weights[i];
        std::size_t j = i;
        for (; j > 0 && weights[j - 1].first > entry.first; --j)
            weights[j] = weights[j - 1];
        weights[j] = entry;
    }
    std::size_t merged = 0;
    for (std::size_t i = 0; i < kept; ++i) {
        if (merged > 0 && weights[merged - 1].first == weights[i].first)
            weights[merged - 1].second += weights[i].second;
        else
            weights[merged++] = weights[i];
    }
    weights.resize(merged);
    double total = 0.0;
    for (const auto& entry : weights)
        total += entry.second;
    for (auto& entry : weights)
        entry.second /= total;
}

}  // namespace rigmesh
