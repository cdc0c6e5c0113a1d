// The union of two closed surfaces along their intersection loop(s) (paper
// 3.2.1): CGAL's corefinement with exact predicates, then the faces near the
// loop remeshed to the target edge length with the loop kept, so no slivers
// remain where the surfaces were cut. Every output vertex says where it came
// from (VertexSource: mesh 0 = `first`, 1 = `second`).
#pragma once

#include <array>
#include <vector>

#include "mesh/TriMesh.h"
#include "part/VertexSource.h"

namespace rigmesh {

struct MeshUnionResult {
    TriMesh mesh;
    VertexSources sources;                 // per output vertex
    std::vector<char> onLoop;              // per output vertex: on an intersection loop
    std::vector<std::array<int, 2>> loop;  // the intersection loop edges
    int remeshedVertices = 0;              // vertices the seam remeshing placed or moved
};

// Throws Error (a message for the user; nothing else changes) when the
// surfaces do not intersect (no loop: they do not touch, or one lies inside
// the other), when either is not a closed surface free of self-intersections,
// or when the union would not be a manifold. `seamEdgeLength` > 0 remeshes the
// faces within two edges of the loop to that length; 0 keeps the raw seam.
//
// `NearOverlap` corefines only the faces near the overlap when it can
// (merge/NearOverlapUnion.h) and CGAL's whole union otherwise; `Whole`
// always runs the whole union. Both give the same mesh, up to the rounding
// of edge-on-edge crossing points (merge/NearOverlapUnion.h).
enum class UnionScope { NearOverlap, Whole };
MeshUnionResult unionMeshes(const TriMesh& first, const TriMesh& second, double seamEdgeLength,
                            UnionScope scope = UnionScope::NearOverlap);

}  // namespace rigmesh
