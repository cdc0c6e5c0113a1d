// Pruned bumps off the middle of a body (paper 2.1 prunes them as
// insignificant branches of the chordal axis). The pruned triangles hang off
// one live sleeve (their former junction); when that sleeve ends up in a
// cylinder's body, the bump's outline is in no region and the surface misses
// it (an ellipse with a bump on top came out without it). Such a
// sleeve becomes a node of the decomposition instead: the branch is split
// there and the sleeve, with its bump, is a connecting region whose patch
// follows the bump's outline.
#pragma once

#include <vector>

#include "axis/ChordalAxis.h"

namespace rigmesh {

// The pruned bump hanging off `sleeve`: how far its outline reaches from the
// chord it hangs on, and that chord's length (both 0 if none hangs there).
struct PrunedBump {
    double height = 0.0;
    double base = 0.0;
};
PrunedBump prunedBumpOf(const ChordalAxis& axis, int sleeve);

// `branch` cut at runs of its sleeves listed in `bumpSleeves` (ascending
// sleeve indices): a piece up to the first sleeve of each run, a piece
// through the run from its first to its last sleeve (when the run has more
// than one), and a piece from the last sleeve on. The run's first and last
// sleeves are the pieces' end nodes. `isRun` tells the run pieces apart.
struct BranchPieces {
    std::vector<AxisBranch> pieces;
    std::vector<bool> isRun;
};
BranchPieces splitAtSleeves(const AxisBranch& branch, const std::vector<int>& bumpSleeves);

}  // namespace rigmesh
