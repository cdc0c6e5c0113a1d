// Bones from an imported mesh's curve skeleton, by the rules a
// sketched part's skeleton follows (paper 2.3, Fig. 6):
// 1. Cycles (a handle, a mesh of genus > 0) are cut: bones form a tree.
// 2. Twigs, branches that end within about a radius of the junction they
//    leave (a bump, a fat tip the flow split in two), are pruned, as the
//    chordal axis prunes its short branches (2.1).
// 3. Junctions closer than their thickness become one joint, so a star's
//    body or a biped's chest gets one branching joint.
// 4. Every branch between junctions and tips is smoothed and down-sampled
//    by Cylindrical Douglas-Peucker in space (rig/DouglasPeucker:
//    TubeSample), threshold and minimum bone relative to the branch's mean
//    radius as for sketches; samples inside a junction's ball are left out,
//    as a sketch's connecting region is (its junction joint stands for them).
// 5. The root is the most central joint; bones point away from it.
#pragma once

#include "autorig/CurveSkeleton.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct CurveRigOptions {
    // As SkeletonOptions: the CDP threshold and the shortest bone inside a
    // branch, as fractions of the branch's mean radius.
    double relativeThreshold = 0.35;
    double relativeMinimumBone = 0.5;
    // Rounds of Laplacian smoothing of each branch's points and radii
    // before CDP (the paper smooths the chordal axis the same way, 2.1).
    int smoothingIterations = 5;
    // A branch from a junction to a tip is a twig when it is shorter than
    // the junction's radius plus this many times the radius at its tip.
    double twigTipFactor = 1.0;
    // Junctions joined by a branch shorter than this times the larger of
    // their radii become one joint.
    double junctionCollapseFactor = 1.0;
};

// `mesh` gives each node its radius (the mean distance to the vertices that
// contracted onto it). Throws Error(AutoRigSkeletonFailed) when no bone can
// be made.
Skeleton skeletonFromCurve(const CurveSkeleton& curve, const TriMesh& mesh,
                           const CurveRigOptions& options = {});

}  // namespace rigmesh
