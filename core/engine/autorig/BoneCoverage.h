// Every region of the mesh near a bone: the farthest vertex at most a
// given distance (15% of the diagonal by default) from all bones. A
// region the curve skeleton left without a bone (a hump over a bull's
// shoulders, a wing the flow reduced to nothing, a trunk beside its arms)
// gets one, most often first: the nearest bone bends towards it (a joint
// inserted and moved into the region, towards the middle of its
// cross-section or, where that lies too deep, towards the far point
// itself, both halves inside the surface),
// else a tip there reaches on into it, else a new branch leaves the
// nearest bone for the middle of the region (autorig/SurfaceProbe). A
// skeleton without branches (a blob's main-axis chain, a rod) is left as
// it is: its body is rigged along its axis.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct BoneCoverageReport {
    int bends = 0;
    int reaches = 0;
    int branches = 0;
    double farthest = 0.0;  // from the bones at the end
};

// `surface` closed and outward (the rig surface's main piece): joints stay
// in it. `points`: the vertices to cover (the mesh the part keeps); a point
// farther than `limit` from all bones is brought within 90% of it. No new
// bone is shorter than `minimumBone`.
BoneCoverageReport coverWithBones(Skeleton& skeleton, const TriMesh& surface,
                                  const std::vector<Vec3>& points, double limit,
                                  double minimumBone);

}  // namespace rigmesh
