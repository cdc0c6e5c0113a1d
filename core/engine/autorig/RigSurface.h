// The surface a mesh's rig is computed on. The mesh itself when it is one
// closed, manifold, self-intersection-free piece, fine enough and small
// enough for the curve skeleton's flow (whose time grows with the vertex count: 0.7 s at
// 4.5k, 2.6 s at 17.7k); its repair (seams joined, small holes filled) when
// that makes it one; otherwise a proxy wrapped around all its pieces
// (autorig/WrapInput, autorig/ProxyWrap). The skeleton and bone heat run on
// this surface; the part keeps the input mesh, whose vertices take their
// weights from it (autorig/WeightTransfer).
#pragma once

#include <vector>

#include "autorig/MeshRepair.h"
#include "autorig/ProxyWrap.h"
#include "autorig/RigProgress.h"
#include "base/Message.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct RigSurfaceOptions {
    // Above this many vertices even a clean mesh is rigged on a proxy, so
    // the flow and the heat run on a bounded surface.
    int directVertexLimit = 6000;
    // A mesh whose edges are on average longer than this fraction of its
    // bounding-box diagonal (a box, a tetrahedron, a low-poly blob: fewer
    // than ten edges across it) is too coarse for the flow, whose skeleton
    // it contracts to a point or a stub, and for bone heat, which gets a
    // value per corner: it is rigged on a proxy too.
    double coarsestEdgeFraction = 0.1;
    MeshRepairOptions repair;
    ProxyWrapOptions wrap;
    // A mesh is refused when rigging it would need more memory than this
    // (estimated per input vertex and face: welding, clustering, the
    // closest-point queries).
    double memoryBudgetBytes = 4.0 * 1024 * 1024 * 1024;
};

struct RigSurface {
    enum class Kind { Input, Repaired, Proxy };
    Kind kind = Kind::Input;
    // Closed, manifold, outward; one piece unless a proxy's pieces lie
    // apart (then `mainPiece` is the largest of them).
    TriMesh mesh;
    TriMesh mainPiece;
    // Per input vertex: the surface vertex it is (Input, Repaired), or -1
    // when it takes the weights of its closest point instead (always for a
    // proxy; a vertex the repair dropped).
    std::vector<int> surfaceVertexOf;
    // Per input vertex: its piece (connected by faces over coincident
    // vertices), -1 for one no face uses; and the number of pieces.
    std::vector<int> pieceOf;
    int pieces = 0;
    // The wrap's parameters (zero unless a proxy).
    double alpha = 0.0;
    double offset = 0.0;
    // What the user is told: repairs, or why a proxy and what it is.
    std::vector<Message> notes;
};

// Throws Error: AutoRigNotFinite, AutoRigFaceOutOfRange for a corrupt mesh,
// AutoRigTooFewFaces when no face has three distinct corners,
// AutoRigOverMemoryBudget, AutoRigCancelled when `progress` says stop.
RigSurface rigSurfaceFor(const TriMesh& input, const RigSurfaceOptions& options = {},
                         const RigProgress& progress = {});

}  // namespace rigmesh
