#include "io/InfluenceLimit.h"

#include <algorithm>
#include <cstddef>

namespace rigmesh {
namespace {

// The limit works alike on bone positions (exports) and bone ids (parts).
template <typename Bone>
using Influences = std::vector<std::pair<Bone, double>>;

template <typename Bone>
Influences<Bone> normalised(Influences<Bone> list) {
    double sum = 0;
    for (const auto& [bone, w] : list)
        sum += w;
    Influences<Bone> out;
    if (!(sum > 0))
        return out;
    for (const auto& [bone, w] : list)
        if (w > 0)
            out.emplace_back(bone, w / sum);
    std::sort(out.begin(), out.end());
    return out;
}

template <typename Bone>
Influences<Bone> limitVertex(Influences<Bone> list, int maxInfluences) {
    std::erase_if(list, [](const auto& entry) { return !(entry.second > 0); });
    if (maxInfluences <= 0 || static_cast<int>(list.size()) <= maxInfluences)
        return normalised(std::move(list));
    // Largest weight first; ties by bone for determinism.
    std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) {
        return a.second != b.second ? a.second > b.second : a.first < b.first;
    });
    const double threshold = list[static_cast<std::size_t>(maxInfluences)].second;
    list.resize(static_cast<std::size_t>(maxInfluences));
    Influences<Bone> shifted;
    for (const auto& [bone, w] : list)
        if (w - threshold > 0)
            shifted.emplace_back(bone, w - threshold);
    return shifted.empty() ? normalised(std::move(list)) : normalised(std::move(shifted));
}

template <typename Weights>
Weights limited(const Weights& weights, int maxInfluences) {
    Weights out;
    out.failedBones = weights.failedBones;
    out.warnings = weights.warnings;
    out.perVertex.reserve(weights.perVertex.size());
    for (const auto& list : weights.perVertex)
        out.perVertex.push_back(limitVertex(list, maxInfluences));
    return out;
}

}  // namespace

SkinWeights limitInfluences(const SkinWeights& weights, int maxInfluences) {
    return limited(weights, maxInfluences);
}

SkinWeightsById limitInfluences(const SkinWeightsById& weights, int maxInfluences) {
    return limited(weights, maxInfluences);
}

}  // namespace rigmesh
