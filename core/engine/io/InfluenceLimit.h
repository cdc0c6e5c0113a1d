// Cutting skin weights to at most N influences per vertex without creases
// (docs/EXCHANGE.md rule 9: glb needs <= 4, normalised).
//
// Dropping the smallest weights and renormalising the rest jumps wherever two
// weights swap rank across the surface (the dropped one goes from w to 0 in
// one step). Instead the largest dropped weight w_{N+1} is subtracted from the
// kept ones before renormalising:
//     w'_i = (w_i - w_{N+1}) / sum_k (w_k - w_{N+1}),  i <= N.
// A weight reaching rank N+1 has fallen to w_{N+1} and so to 0 already: the
// result is continuous in the input weights, and vertices with at most N
// influences are unchanged. Where every kept weight equals w_{N+1} (a tie
// across the cut) the plain renormalisation of the N largest is used.
#pragma once

#include "part/BoneWeights.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh {

// `maxInfluences` <= 0 keeps every influence (weights are still normalised).
// Output lists are sorted by bone, weights > 0 summing to 1. A vertex with no
// influence (or all zero) stays empty.
SkinWeights limitInfluences(const SkinWeights& weights, int maxInfluences);
// The same on a part's weights (bones by id).
SkinWeightsById limitInfluences(const SkinWeightsById& weights, int maxInfluences);

}  // namespace rigmesh
