// Bones kept inside the rig surface (paper 2.3: the skeleton lies inside
// the shape). A straight bone between two joints of a thin, bent limb cuts
// the bend's corner, and mirroring the skeleton (rig/SkeletonSymmetry) can
// move a joint of a thin limb out of it. Each joint outside moves to the
// middle of its cross-section (a tip first slides along its bone until it
// is inside), and a bone that leaves the surface between its joints is
// split where it leaves farthest, the new joint at the middle of the
// cross-section there perpendicular to the bone (autorig/SurfaceProbe).
// A joint moves only where no point of `cover` that its bones kept within
// `coverage` of them (or within the farthest point's distance at the
// start, if farther) is left farther from every bone (in a sheet the
// cross-section's middle can lie far from the limb; a tip then stays where
// it slid in).
#pragma once

#include <vector>

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
BonesInsideReport keepBonesInside(Skeleton& skeleton, const TriMesh& surface, double minimumBone,
                                  const std::vector<Vec3>& cover = {}, double coverage = 0.0);

// A skeleton computed on a proxy wrapped around the mesh (autorig/ProxyWrap)
// lies inside the proxy, which is fatter than the mesh by at least the
// wrap's offset and bridges what alpha cannot enter: a joint of a thin limb
// or a tip can lie outside the mesh the part keeps, and a rigger sees its
// bone poke out of the limb. Each joint outside `mesh` by ray-cast parity
// (autorig/SurfaceProbe, InsideBy::RayParity: an eye inside a head is
// outside, as Blender sees it), or closer to its surface than 1e-4 of its
// size, moves to the nearest place inside it within twice its depth in the
// proxy plus `reach` (the wrap's alpha): into the middle of the limb's
// cross-section there when that is inside and within the half chord the
// search ray measured, else halfway from the wall it met to the next (a
// tip may also slide along its bone into the mesh). A move is
// kept only when every bone at the joint stays inside `surface` (9 points
// per bone, joints included, by winding number) and no shorter than
// `minimumBone`, and every vertex of `mesh` stays within `coverage` of a
// bone (or within its farthest before, if farther: autorig/BoneCoverage);
// where the mesh has no inside near the joint (a sheet, a wing without
// thickness) the joint stays. The tree, its leaves and its bones stay as
// they are; only joints move.
struct JointsInMeshLimits {
    double reach = 0.0;
    double minimumBone = 0.0;
    double coverage = 0.0;
};
struct JointsInMeshReport {
    int jointsMoved = 0;
    int jointsOutside = 0;  // left outside at the end
};
JointsInMeshReport keepJointsInMesh(Skeleton& skeleton, const TriMesh& mesh, const TriMesh& surface,
                                    const JointsInMeshLimits& limits);

}  // namespace rigmesh
