// Bones kept inside the rig surface (paper 2.3: the skeleton lies inside
// the shape). A straight bone between two joints of a thin, bent limb cuts
// the bend's corner, and mirroring the skeleton (rig/SkeletonSymmetry) can
// move a joint of a thin limb out of it. Each joint outside moves to the
// middle of its cross-section (a tip first slides along its bone until it
// is inside), and a bone that leaves the surface between its joints is
// split where it leaves farthest, the new joint at the middle of the
// cross-section there perpendicular to the bone (autorig/SurfaceProbe).
#pragma once

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct BonesInsideReport {
    int jointsMoved = 0;
    int bonesSplit = 0;
    int pointsOutside = 0;  // left outside at the end (9 per bone, joints included)
};

// `surface` closed and outward. No split makes a bone shorter than
// `minimumBone` (rig/ShortBones.h). Topology changes only by splits.
BonesInsideReport keepBonesInside(Skeleton& skeleton, const TriMesh& surface, double minimumBone);

}  // namespace rigmesh
