// Skin weights keyed by stable bone ids. A Part stores its
// weights by BoneId, so a bone that goes (pruned, deleted, collapsed) never
// shifts the other bones' weights. The solvers, the GPU upload and the
// exporters want dense arrays by bone position (index in skeleton.bones());
// they convert at their boundary with weightsById / weightsByIndex.
#pragma once

#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "base/Message.h"
#include "rig/BoneHeatSolver.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// Per vertex: (bone id, weight), sorted by bone id.
using WeightsById = std::vector<std::vector<std::pair<BoneId, double>>>;
// Per vertex: (bone id, distance) of the closest visible bone(s).
using ClosestBonesById = std::vector<std::vector<std::pair<BoneId, double>>>;

// A part's skin weights.
struct SkinWeightsById {
    // Per vertex: (bone id, weight) sorted by bone id; weights > 0 summing to 1.
    WeightsById perVertex;
    // Bones whose heat solve failed and which use nearest-bone weights instead.
    std::vector<BoneId> failedBones;
    // Notes for the user when anything fell back; empty otherwise. Documents
    // keep them as ids and arguments (part/PartJson.cpp), never as English.
    std::vector<Message> warnings;

    bool operator==(const SkinWeightsById&) const = default;
};

// A solver's result (bone index = position in skeleton.bones()) by bone id.
SkinWeightsById weightsById(const Skeleton& skeleton, const SkinWeights& weights);
// The dense form by bone position. Throws Error if a weight or failed bone
// names a bone the skeleton does not have.
SkinWeights weightsByIndex(const Skeleton& skeleton, const SkinWeightsById& weights);
ClosestBonesById closestById(const Skeleton& skeleton, const ClosestBones& closest);
// Entries for bones the skeleton no longer has are dropped.
ClosestBones closestByIndex(const Skeleton& skeleton, const ClosestBonesById& closest);

// Bone id -> position in skeleton.bones(), for per-weight lookups in hot
// loops (skinning, uploads): a plain array for the usual compact ids, a hash
// map only for ids far beyond the bone count (a hand-edited file).
class BoneIndexTable {
  public:
    explicit BoneIndexTable(const Skeleton& skeleton);
    // -1 for a bone the skeleton does not have.
    int operator[](BoneId id) const {
        if (id < dense_.size())
            return dense_[id];
        const auto found = sparse_.find(id);
        return found == sparse_.end() ? -1 : found->second;
    }
    // True when every id is in the plain array (ids below its size).
    bool coversAllInArray() const { return sparse_.empty(); }
    std::size_t arraySize() const { return dense_.size(); }

  private:
    std::vector<int> dense_;
    std::unordered_map<BoneId, int> sparse_;
};

// The bone with the largest weight in a vertex's list (the first of equals);
// the list must not be empty.
BoneId leadingBone(const std::vector<std::pair<BoneId, double>>& weights);
// Per bone: how many vertices have it as their largest weight (paper 3.2's
// "most influential" bones). Bones that lead no vertex are absent.
std::map<BoneId, int> leadingVertexCounts(const WeightsById& weights);

// Sorts by bone, merges repeated bones, drops non-positive weights and
// rescales to sum 1; an empty list stays empty.
void normaliseWeights(std::vector<std::pair<BoneId, double>>& weights);

}  // namespace rigmesh
