#include "part/BoneWeights.h"

#include <algorithm>
#include <map>

#include "base/Error.h"

namespace rigmesh {

WeightsById weightsById(const Skeleton& skeleton, const SkinWeights& weights) {
    WeightsById result(weights.perVertex.size());
    for (std::size_t v = 0; v < weights.perVertex.size(); ++v) {
        for (const auto& [bone, w] : weights.perVertex[v])
            result[v].emplace_back(skeleton.bones()[bone].id, w);
        std::sort(result[v].begin(), result[v].end());
    }
    return result;
}

SkinWeights weightsByIndex(const Skeleton& skeleton, const WeightsById& weights) {
    SkinWeights result;
    result.perVertex.resize(weights.size());
    for (std::size_t v = 0; v < weights.size(); ++v) {
        for (const auto& [bone, w] : weights[v]) {
            if (!skeleton.hasBone(bone))
                throw Error("A skin weight refers to bone " + std::to_string(bone) +
                            ", which the skeleton does not have.");
            result.perVertex[v].emplace_back(skeleton.indexOfBone(bone), w);
        }
        std::sort(result.perVertex[v].begin(), result.perVertex[v].end());
    }
    return result;
}

ClosestBonesById closestById(const Skeleton& skeleton, const ClosestBones& closest) {
    ClosestBonesById result(closest.size());
    for (std::size_t v = 0; v < closest.size(); ++v)
        for (const auto& [bone, d] : closest[v])
            result[v].emplace_back(skeleton.bones()[bone].id, d);
    return result;
}

ClosestBones closestByIndex(const Skeleton& skeleton, const ClosestBonesById& closest) {
    ClosestBones result(closest.size());
    for (std::size_t v = 0; v < closest.size(); ++v)
        for (const auto& [bone, d] : closest[v])
            if (skeleton.hasBone(bone))
                result[v].emplace_back(skeleton.indexOfBone(bone), d);
    return result;
}

std::vector<int> leadingVertexCounts(const SkinWeights& weights, int boneCount) {
    std::vector<int> counts(std::max(boneCount, 0), 0);
    for (const auto& list : weights.perVertex) {
        if (list.empty())
            continue;
        const int bone = std::max_element(list.begin(), list.end(), [](auto& a, auto& b) {
                             return a.second < b.second;
                         })->first;
        if (bone >= 0 && bone < boneCount)
            ++counts[bone];
    }
    return counts;
}

void normaliseWeights(std::vector<std::pair<BoneId, double>>& weights) {
    std::map<BoneId, double> merged;
    for (const auto& [bone, w] : weights)
        if (w > 0.0)
            merged[bone] += w;
    weights.assign(merged.begin(), merged.end());
    double total = 0.0;
    for (const auto& entry : weights)
        total += entry.second;
    for (auto& entry : weights)
        entry.second /= total;
}

}  // namespace rigmesh
