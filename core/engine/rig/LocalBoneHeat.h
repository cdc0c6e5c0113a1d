// Local skin weight re-computation after a merge (paper 3.2.2): only the
// vertices near the merge boundary whose weights are clearly wrong, a
// transition band around them and the bones they involve are solved again,
// with the weights of the excluded neighbours as boundary values.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "part/BoneWeights.h"
#include "rig/BoneHeatSolver.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct LocalBoneHeatOptions {
    BoneHeatOptions heat;
    // The paper's c is 1.5. Our heat spreads further (Pinocchio's one-ring
    // area, BoneHeatSolver.h), and at 1.5 the camel session's 90th
    // percentile of the local-global difference reached 0.072; at 2.0 it
    // stays within 0.016-0.028 for about a third more vertices (measured
    // with `rigmesh run resources/recipes/camel.json --compare-global`).
    double transitionFactor = 2.0;
};

struct LocalBoneHeatResult {
    WeightsById weights;          // every vertex; unchanged outside `recomputed`
    std::vector<int> failedTest;  // "red": the inclusion test put them in
    std::vector<int> transition;  // "yellow": the transition band
    std::vector<BoneId> bones;    // bones involved, sorted
    int verticesInvolved() const { return static_cast<int>(failedTest.size() + transition.size()); }
};

// `weights` are the carried weights (an empty list for a vertex without any),
// taken by value: the result's table is them with the re-skinned vertices
// replaced (a caller done with its table moves it in instead of copying);
// `seeds` the merge boundary, where the breadth-first inclusion test starts;
// `unknown` the seeds with no trustworthy weights, included whatever the test
// says; `extraBones` bones that must take part (a new connecting bone).
// Throws Error if the skeleton has no bone.
LocalBoneHeatResult recomputeWeightsLocally(const TriMesh& mesh, const Skeleton& skeleton,
                                            WeightsById weights, const std::vector<int>& seeds,
                                            const std::vector<int>& unknown,
                                            const std::vector<BoneId>& extraBones = {},
                                            const LocalBoneHeatOptions& options = {});

// The whole part's weights as in section 2.4 (every vertex tested for
// visibility), keyed by bone id: the global re-computation.
WeightsById recomputeWeightsGlobally(const TriMesh& mesh, const Skeleton& skeleton,
                                     const BoneHeatOptions& options = {});

}  // namespace rigmesh
