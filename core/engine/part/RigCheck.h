// Check Rig: what an artist must fix before a rig is
// trusted in another tool, listed by vertex and by bone so the studio can
// select each. Unlike Part::validate() (which refuses broken data) these are
// legal states a paint stroke or a clean-up can leave behind.
#pragma once

#include <vector>

#include "part/Part.h"

namespace rigmesh {

struct RigCheckOptions {
    int maxInfluences = 4;       // glTF's four; over this a vertex is listed
    double sumTolerance = 1e-6;  // how far from 1 a vertex's sum may be
};

struct RigCheckReport {
    // Vertices with no weight at all (they would not move with any bone).
    std::vector<int> unweightedVertices;
    // Bones that are no vertex's largest weight (paper 3.2 prunes such bones
    // after a merge; paint can make more), by id.
    std::vector<BoneId> bonesLeadingNoVertex;
    // Vertices weighted by more than maxInfluences bones.
    std::vector<int> verticesOverInfluences;
    // Vertices whose weights do not sum to 1 within sumTolerance.
    std::vector<int> verticesWithSumsOff;

    bool clean() const {
        return unweightedVertices.empty() && bonesLeadingNoVertex.empty() &&
               verticesOverInfluences.empty() && verticesWithSumsOff.empty();
    }
};

// Throws Error if maxInfluences < 1 or the tolerance is not positive. A part
// without a skeleton (an unrigged import) reports every vertex unweighted.
RigCheckReport checkRig(const Part& part, const RigCheckOptions& options = {});

}  // namespace rigmesh
