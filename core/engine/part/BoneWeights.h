// Skin weights keyed by stable bone ids (issue 12 item 1). A Part stores its
// weights by bone position (what solvers, skinning and the GPU want), but
// positions shift when a bone goes; topology and bone edits convert to ids,
// work there, and convert back against the final skeleton.
#pragma once

#include <utility>
#include <vector>

#include "rig/BoneHeatSolver.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// Per vertex: (bone id, weight), sorted by bone id.
using WeightsById = std::vector<std::vector<std::pair<BoneId, double>>>;
// Per vertex: (bone id, distance) of the closest visible bone(s).
using ClosestBonesById = std::vector<std::vector<std::pair<BoneId, double>>>;

WeightsById weightsById(const Skeleton& skeleton, const SkinWeights& weights);
// Throws Error if a weight names a bone the skeleton does not have.
SkinWeights weightsByIndex(const Skeleton& skeleton, const WeightsById& weights);
ClosestBonesById closestById(const Skeleton& skeleton, const ClosestBones& closest);
// Entries for bones the skeleton no longer has are dropped.
ClosestBones closestByIndex(const Skeleton& skeleton, const ClosestBonesById& closest);

// Per bone (position in skeleton.bones()): how many vertices have it as
// their largest weight (paper 3.2's "most influential" bones).
std::vector<int> leadingVertexCounts(const SkinWeights& weights, int boneCount);

// Sorts by bone, merges repeated bones, drops non-positive weights and
// rescales to sum 1; an empty list stays empty.
void normaliseWeights(std::vector<std::pair<BoneId, double>>& weights);

}  // namespace rigmesh
