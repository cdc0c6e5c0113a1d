// The curve skeleton of a closed mesh by mean curvature flow (Tagliasacchi,
// Alhashim, Olson and Zhang 2012; CGAL's Mean_curvature_flow_skeletonization):
// the surface contracts to a medially centred curve, and every mesh vertex
// ends up at one curve node. It stands in for the chordal axis a sketched
// part has (paper 2.1) when the part comes from a file. Only
// CurveSkeleton.cpp sees CGAL.
#pragma once

#include <array>
#include <vector>

#include "autorig/RigProgress.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct CurveSkeleton {
    std::vector<Vec3> nodes;
    // Per node: the mesh vertices that contracted onto it (may be empty).
    std::vector<std::vector<int>> nodeVertices;
    std::vector<std::array<int, 2>> edges;
};

// `mesh` must be closed, manifold and one piece (autorig/MeshRepair).
// Reports progress between 0 and 1 and throws Error(AutoRigCancelled) when
// `progress` says stop, Error(AutoRigFlowContracted) when the flow gives no
// curve.
CurveSkeleton extractCurveSkeleton(const TriMesh& mesh, const RigProgress& progress = {});

}  // namespace rigmesh
