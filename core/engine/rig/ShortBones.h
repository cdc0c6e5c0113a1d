// One shortest bone for every edit that makes bones: a cut (paper 3.1), a
// bone split or delete (3.3), a merge's split or connect (3.2) and auto-rig.
// A bone shorter than half the surface's mean edge leads next to no vertex
// (bone heat cannot tell it from its joint at the mesh's resolution, 2.4),
// and importers drop bones that short as degenerate. Each edit keeps it its
// own way: a crossing or split point within it of a joint snaps to the
// joint, and an edit whose piece or part would be left with only such a
// bone is refused with the lengths (docs/CUTTING.md, docs/MERGING.md).
#pragma once

#include "mesh/TriMesh.h"
#include "rig/Skeleton.h"

namespace rigmesh {

// Half the mean edge length of `mesh` (0 for a mesh without faces).
double minimumBoneLength(const TriMesh& mesh);
// The same from a mean edge length the caller has already measured.
double minimumBoneLength(double meanEdgeLength);

// The shortest bone of the skeleton and its length (none: no bones).
struct ShortestBone {
    BoneId bone = 0;
    double length = 0.0;
};
std::optional<ShortestBone> shortestBone(const Skeleton& skeleton);

// Collapses every bone shorter than `minimum` into its neighbour, shortest
// first: a bone with a leaf end gives up that end (the bone it hangs from
// reaches as before), a bone between two branching joints becomes one joint
// at its middle. A skeleton of one bone is left as it is (the caller
// refuses it). Returns how many bones went. The root stays (a collapsed
// bone's joint that stays keeps its id), unless it is left a leaf: then
// the skeleton's most central joint; the bones are oriented from it again.
int collapseShortBones(Skeleton& skeleton, double minimum);

}  // namespace rigmesh
