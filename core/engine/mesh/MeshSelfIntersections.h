// Counting self-intersecting face pairs with CGAL, kept behind a CGAL-free
// interface so that only MeshSelfIntersections.cpp pays CGAL's compile time.
#pragma once

#include <array>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Number of pairs of distinct faces that intersect other than in a shared
// vertex or edge, by the rule of CGAL::Polygon_mesh_processing::
// self_intersections (exact predicates, CGAL box intersection) applied to the
// triangle soup directly: sharing is decided by vertex index, so non-manifold
// and non-orientable input works, and no halfedge mesh has to be built.
// Faces whose corners are collinear are skipped, as CGAL does (they are
// degenerate faces). Indices must be in range and coordinates finite.
int countSelfIntersectingFacePairs(const TriMesh& mesh);

// The same pairs, each as two face indices (smaller first), sorted: where
// they are, for a message that says so.
std::vector<std::array<int, 2>> selfIntersectingFacePairs(const TriMesh& mesh);

// The same pairs for a surface that is its own mirror image in the plane
// z = 0, `mirror` giving each vertex's image (as SketchSurface::mirror does):
// where the proof of mesh/MirroredHeightField.h applies (each half a height
// field over the plane but for a few folds), only its suspects, the faces
// over the folds, are tested, usually none; else, when the image is exact,
// whether any pair exists is decided on about half the faces (the upper half
// and those at the plane), and the pairs are listed only if one does;
// otherwise all faces are tested.
std::vector<std::array<int, 2>> selfIntersectingFacePairs(const TriMesh& mesh,
                                                          const std::vector<int>& mirror);

// The same count from PMP::self_intersections itself on a CGAL::Surface_mesh
// (after orienting the soup), or -1 when the soup is not an orientable
// manifold. Two to three times slower; the reference the soup count is
// checked against.
int countSelfIntersectingFacePairsWithSurfaceMesh(const TriMesh& mesh);

}  // namespace rigmesh
