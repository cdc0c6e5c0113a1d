// Making an imported mesh fit for rigging: the curve
// skeleton needs a closed, manifold, single-component triangle mesh, and bone
// heat needs an outward one. What is safe to repair is repaired and listed;
// what is not is refused with a message naming the problem. Only this file's
// .cpp sees CGAL.
#pragma once

#include <vector>

#include "base/Message.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct MeshRepairOptions {
    // A hole is filled (CGAL PMP triangulate, refine and fair) when its
    // border is at most this many mean edge lengths (a few faces missing)
    // or this fraction of the mesh's bounding-box diagonal; a larger
    // opening is a missing piece of shape, refused.
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

// Repairs in this order: coincident vertices joined (seams stitched), faces
// with a repeated corner and duplicate faces dropped, unused vertices
// dropped, the soup oriented and vertices where sheets touch split, faces
// without area removed, small holes filled, the faces turned outward. Then
// refuses (rigmesh::Error with an AutoRig* message) a mesh that is still
// open, of several pieces, or self-intersecting, or too small. Throws also
// on indices out of range or non-finite positions.
RepairedMesh repairForRigging(const TriMesh& input, const MeshRepairOptions& options = {});

}  // namespace rigmesh
