// Rigging an unrigged part, usually an imported mesh (the paper
// names it as future work): the mesh repaired where that is safe
// (autorig/MeshRepair), a curve skeleton by mean curvature flow
// (autorig/CurveSkeleton), bones by the sketches' rules
// (autorig/SkeletonFromCurve), and bone heat with every vertex tested for
// visibility (paper 2.4). The result is an ordinary rigged part: the cut,
// merge, bone and weight tools take it like a sketched one.
#pragma once

#include <vector>

#include "autorig/MeshRepair.h"
#include "autorig/RigProgress.h"
#include "autorig/SkeletonFromCurve.h"
#include "part/Part.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh {

struct AutoRigOptions {
    MeshRepairOptions repair;
    CurveRigOptions bones;
    BoneHeatOptions heat;
};

struct AutoRigResult {
    Part part;
    // Per vertex of part.mesh: the vertex of the input part it came from,
    // or -1 for one a filled hole added.
    std::vector<int> sourceVertex;
    // What the repair did (empty when the mesh was used as it is).
    std::vector<Message> repairs;
    // Vertices that saw no bone from inside and took their closest bone's
    // heat (a thin fold, a bump): none is left unweighted.
    int verticesWithoutVisibleBone = 0;
};

// Throws Error: AutoRigPartIsRigged for a part with a skeleton,
// AutoRigNoSurface for one without faces, the repair's refusals,
// AutoRigSkeletonFailed, AutoRigCancelled when `progress` says stop. The
// part given is never changed.
AutoRigResult autoRigPart(const Part& part, const AutoRigOptions& options = {},
                          const RigProgress& progress = {});

}  // namespace rigmesh
