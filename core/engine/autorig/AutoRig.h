// Rigging an unrigged part, usually an imported mesh (the paper names it as
// future work). The rig is computed on a clean surface (autorig/RigSurface:
// the mesh itself when it is one closed piece, else its repair or a proxy
// wrapped around all its pieces): a curve skeleton by mean curvature flow
// (autorig/CurveSkeleton), bones by the sketches' rules
// (autorig/SkeletonFromCurve), bone heat with every vertex tested for
// visibility (paper 2.4). The part keeps its own mesh, every piece and
// vertex as it was; each vertex takes the weights of its closest point of
// that surface (autorig/WeightTransfer), and a small piece that floats
// apart (an eye, a tooth, a button) follows one bone as a whole.
#pragma once

#include <vector>

#include "autorig/RigProgress.h"
#include "autorig/RigSurface.h"
#include "autorig/SkeletonFromCurve.h"
#include "part/Part.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh {

struct AutoRigOptions {
    RigSurfaceOptions surface;
    CurveRigOptions bones;
    BoneHeatOptions heat;
    // A piece of the mesh (connected by faces) whose bounding box is at
    // most this fraction of the whole mesh's follows one bone as a whole.
    double floatingPieceFraction = 0.1;
};

struct AutoRigResult {
    // The input part's mesh with a skeleton and weights: unchanged but for
    // faces that repeat a corner, which are left out.
    Part part;
    // The surface the skeleton and the heat were computed on: the mesh
    // itself, its repair or the proxy (rigmesh rig --debug-proxy).
    TriMesh rigSurface;
    RigSurface::Kind surfaceKind = RigSurface::Kind::Input;
    // What the rig had to work around, for the user: repairs, why a proxy
    // and what it is, the pieces that follow one bone.
    std::vector<Message> repairs;
    // Vertices of the rig surface that saw no bone from inside and took
    // their closest bone's heat (a thin fold, a bump).
    int verticesWithoutVisibleBone = 0;
    // Pieces of the mesh that follow one bone as a whole.
    int floatingPieces = 0;
};

// Throws Error: AutoRigPartIsRigged for a part with a skeleton,
// AutoRigNoSurface for one without faces, rigSurfaceFor's refusals
// (non-finite numbers, no usable triangle, over the memory budget),
// AutoRigSkeletonFailed, AutoRigCancelled when `progress` says stop. The
// part given is never changed.
AutoRigResult autoRigPart(const Part& part, const AutoRigOptions& options = {},
                          const RigProgress& progress = {});

}  // namespace rigmesh
