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
//    A limb CDP gives one bone from its junction keeps a joint where it
//    leaves the junction (its neck, else the ball's edge), as a sketch's
//    cylindrical region ends where its connecting region begins (Fig. 6).
// 5. The root is the thickest branching joint (the torso), else the most
//    central joint; bones point away from it.
// A twig that reaches far from its junction is never pruned (a trunk's
// base, a head), so every region of the body stays near a bone; a chain
// without branches that covers the body worse than its main axis would
// (a blob) is replaced by that axis (autorig/AxisChain).
#pragma once

#include "autorig/CurveSkeleton.h"
#include "base/Message.h"
#include "rig/Skeleton.h"

namespace rigmesh {

struct CurveRigOptions {
    // As SkeletonOptions: the CDP threshold and the shortest bone inside a
    // branch, as fractions of the branch's mean radius.
    double relativeThreshold = 0.35;
    double relativeMinimumBone = 0.5;
    // For a branch longer than its mean radius over this share, those
    // fractions are of this share of its length instead (a thin limb).
    double thinLimbLengthShare = 0.08;
    // Rounds of Laplacian smoothing of each branch's points and radii
    // before CDP (the paper smooths the chordal axis the same way, 2.1).
    int smoothingIterations = 5;
    // A branch from a junction to a tip is a twig when it is shorter than
    // the junction's radius plus this many times the radius at its tip.
    double twigTipFactor = 1.0;
    // Junctions joined by a branch shorter than this times the larger of
    // their radii become one joint.
    double junctionCollapseFactor = 1.0;
    // A twig whose vertices reach farther than this fraction of the mesh's
    // bounding-box diagonal from its junction is kept (a part of the body).
    double keepReachFraction = 0.1;
    // A skeleton without a branch whose farthest vertex lies farther than
    // this fraction of the diagonal from its bones gives way to a chain
    // along the main axis (autorig/AxisChain) when that one covers better.
    double coverageFraction = 0.15;
};

// `mesh` gives each node its radius (the mean distance to the vertices that
// contracted onto it). Throws Error(AutoRigFlowGaveNoCurve,
// AutoRigCurveTooShort or AutoRigSkeletonFailed) when no bone can be made.
Skeleton skeletonFromCurve(const CurveSkeleton& curve, const TriMesh& mesh,
                           const CurveRigOptions& options = {});

// Whether `id`, thrown by extractCurveSkeleton or skeletonFromCurve, says the
// flow gave no usable skeleton (the shape is a blob: autorig/AutoRig falls
// back to a chain along its main axis). Kept beside the throws it names.
bool flowGaveNoSkeleton(MessageId id);

// The joints with one bone (the limbs' ends).
int leafCount(const Skeleton& skeleton);

}  // namespace rigmesh
