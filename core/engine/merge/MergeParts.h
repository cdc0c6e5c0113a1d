// Merging two rigged parts into one (paper 3.2): skeletons joined (snap,
// split or connect), surfaces united along their intersection loop and
// smoothed locally, bones that lead no vertex pruned, and skin weights
// re-computed locally (3.2.2) or globally (2.4). The result is validated.
#pragma once

#include <map>
#include <vector>

#include "base/Statistics.h"
#include "merge/SkeletonJoin.h"
#include "part/BoneWeights.h"
#include "part/Part.h"
#include "part/VertexSource.h"

namespace rigmesh {

enum class Reskin { Local, Global };

struct MergeRequest {
    SkeletonJoinRequest join;
    Reskin reskin = Reskin::Local;
    // The seam is remeshed to this edge length; 0 = the target's mean edge.
    double edgeLength = 0.0;
    // Also solve the global weights, to report their time and difference.
    bool compareGlobal = false;
    BoneHeatOptions heat;
};

// What Table 1 reports for one merge, plus the other stages' times.
struct MergeStats {
    int vertices = 0, bones = 0;                  // of the merged part
    int verticesInvolved = 0, bonesInvolved = 0;  // in the re-skin (all, for global)
    int prunedBones = 0;
    int smoothedVertices = 0;
    double unionMs = 0, smoothingMs = 0, reskinMs = 0, totalMs = 0;
    double globalMs = -1;  // with compareGlobal
    // The per-vertex L1 difference of the local and the global weights (with
    // compareGlobal): 90th and 99th percentiles and mean.
    double p90WeightDifference = -1, p99WeightDifference = -1, meanWeightDifference = -1;
};

struct MergeResult {
    Part part;
    Vec3 draggedTranslation = Vec3::Zero();    // what snapping moved the dragged part by
    std::map<JointId, JointId> draggedJoints;  // dragged id -> merged id (absent: pruned)
    std::vector<BoneId> prunedBones;           // merged ids no longer in the skeleton
    // Bones the request made (the connecting bone, the split's halves): kept
    // even when, after the re-skin, they lead no vertex (a bone for posing).
    std::vector<BoneId> requestedBones;
    std::vector<int> movedVertices;  // by the seam smoothing (output indices)
    VertexSources sources;           // 0 = target, 1 = dragged
    MergeStats stats;
};

// `dragged` is given in the target's coordinates. Throws Error (message for
// the user) when the merge is refused: unknown joints, parts that do not
// overlap, a union that is not a manifold.
MergeResult mergeParts(const Part& target, const Part& dragged, const MergeRequest& request);

// The per-vertex L1 difference of two weightings of the same vertices.
std::vector<double> weightDifferences(const WeightsById& a, const WeightsById& b);

}  // namespace rigmesh
