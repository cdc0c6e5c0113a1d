// Constrained Delaunay triangulations of simple polygons (paper 2.1, [Chew 1989]).
// CGAL stays inside ConstrainedTriangulation.cpp: this header is plain data.
#pragma once

#include <array>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

// The CDT of a simple polygon without Steiner points: the triangles cover the
// polygon exactly and every triangle vertex is a polygon vertex.
struct PolygonTriangulation {
    std::vector<Vec2> points;                   // the polygon's vertices, counter-clockwise
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise, indices into points
    // neighbors[t][k]: the triangle across the edge opposite corner k
    // (edge triangles[t][k+1] -> triangles[t][k+2]), or -1 across a polygon edge.
    std::vector<std::array<int, 3>> neighbors;
};

// Triangulates a simple, counter-clockwise polygon. Throws rigmesh::Error when
// the polygon cannot be triangulated (fewer than 3 points, self-overlap).
PolygonTriangulation triangulatePolygon(const std::vector<Vec2>& polygon);

// A triangulated planar patch: the region bounded by `boundary` (a simple,
// counter-clockwise loop) with extra interior points inserted. Used to cover
// connecting regions (our replacement for GridMesh, paper 2.2 / Fig. 3e).
struct PatchTriangulation {
    std::vector<Vec2> points;                   // boundary points first, then inserted points
    std::vector<std::array<int, 3>> triangles;  // counter-clockwise, inside the boundary only
};

// Triangulates the polygon `boundary` with `interiorPoints` as extra vertices
// (those outside the boundary are ignored). Afterwards every interior edge
// joining two boundary points for which `isRimPoint` is true is split at its
// midpoint, so that no triangle edge except a boundary edge joins two rim points.
PatchTriangulation triangulatePatch(const std::vector<Vec2>& boundary,
                                    const std::vector<Vec2>& interiorPoints,
                                    const std::vector<bool>& isRimPoint);

}  // namespace rigmesh
