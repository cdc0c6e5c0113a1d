// Making an imported mesh fit for rigging as it is: the curve skeleton needs
// a closed, manifold, single-component triangle mesh, and bone heat needs an
// outward one. What is safe to repair is repaired and listed; when the mesh
// is still not one such piece, the reason is given and the rig is built on
// a wrapped proxy instead (autorig/RigSurface). Only this file's .cpp sees
// CGAL.
#pragma once

#include <optional>
#include <vector>

#include "base/Message.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct MeshRepairOptions {
    // A hole is filled (CGAL PMP triangulate, refine and fair) when its
    // border is at most this many mean edge lengths (a few faces missing)
    // or this fraction of the mesh's bounding-box diagonal; a larger
    // opening is a missing piece of shape, left to the proxy.
    double smallHoleEdges = 12.0;
    double smallHoleFraction = 0.05;
};

struct RepairedMesh {
    TriMesh mesh;
    // Per vertex of `mesh`: the input vertex it is (or a copy of), or -1 for
    // a vertex a filled hole created.
    std::vector<int> sourceVertex;
    // What was repaired, for the user; empty when the mesh was fine (and
    // then `mesh` is the input, vertex for vertex).
    std::vector<Message> repairs;
};

// Either the repaired mesh or why there is none.
struct RepairAttempt {
    std::optional<RepairedMesh> repaired;
    // When `repaired` is empty: AutoRigSeveralPieces, AutoRigOpenBorder,
    // AutoRigNotManifold, AutoRigSelfIntersecting or AutoRigTooFewFaces.
    Message reason;
};

// Whether `mesh` is one closed, manifold, outward piece without degenerate
// or repeated faces, unused vertices or self-intersections: used as it is.
bool fitForRigging(const TriMesh& mesh);

// Repairs in this order: coincident vertices joined (seams stitched), faces
// with a repeated corner and duplicate faces dropped, unused vertices
// dropped, the soup oriented and vertices where sheets touch split, faces
// without area removed, small holes filled, the faces turned outward. A mesh
// that is then still open, of several pieces, self-intersecting or of fewer
// than 4 faces gives the reason instead. `input` must have finite positions
// and indices in range.
RepairAttempt repairForRigging(const TriMesh& input, const MeshRepairOptions& options = {});

}  // namespace rigmesh
