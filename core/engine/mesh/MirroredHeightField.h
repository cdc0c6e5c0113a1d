// A proof, from the shape alone, that a surface which is exactly its own
// mirror image in the plane z = 0 does not cross itself: the sketch surfaces
// (surface/SketchSurface.h) are built as an upper half over the sketch
// plane and its mirror image, and after smoothing their upper half is
// almost always still the graph of a height over the plane, or nearly: a
// few faces by the outline, where the surface stands upright, may fold over.
// Deciding that takes one exact orientation per upper face and a look at
// the outline, where the pairwise test (mesh/MeshSelfIntersections.h) boxes
// and compares every face; only the faces over a fold are left to it.
#pragma once

#include <optional>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// The faces among which any crossing of `mesh` must lie (pairs of faces
// that intersect other than in a shared vertex or edge, the rule of
// mesh/MeshSelfIntersections.h): none when the mesh is proven free of them;
// nothing at all when the proof does not apply. It applies when the mesh is
// exactly its own mirror image (mesh/MeshMirror.h: `mirror` gives each
// vertex's image, and each face is the image of its image, so no face is
// there twice), a vertex on the plane is its own image, and every face
// lies on one side: its corners' heights all >= 0 with one > 0 (the upper
// faces U), or the same below; no directed edge is in two faces of U, and
// the edges of U without their reverse in U (its boundary) form one cycle
// whose projection P onto the plane is a simple polygon. Then:
//   - counting each face of U over a point of the plane +1 if P turns it as
//     the polygon turns and -1 if not (a fold; a face seen edge-on counts
//     0), the sum is the polygon's winding number there, 0 or 1. Away from
//     the folds every face counts +1, so at most one face of U lies over
//     such a point: two faces of U that are not both over a fold (within
//     the suspects: the faces whose box in the plane meets a fold's) meet in
//     their shared corners' hull only. With no fold, P is one to one on U: U
//     is the graph of a height;
//   - a face F of U and the image G' of a face G of U meet in the plane
//     only (F above it, G' below), where G' is G; unless F and G are both
//     suspects they meet in their shared corners' hull within the plane,
//     whose corners lie on the plane, are their own images and so corners
//     of G' too;
//   - two lower faces are the images of two upper ones.
// Two faces sharing an edge are coplanar with their third corners on one
// side of it only if one is a fold (the third corners of two faces that P
// turns alike lie on opposite sides of the edge's image; an upper and a
// lower face so placed stand upright on the plane, edge-on to P).
// The suspects are the upper ones and their images, to be tested pairwise.
std::optional<std::vector<int>> mirroredHeightFieldSuspects(const TriMesh& mesh,
                                                            const std::vector<int>& mirror);

// Whether the mesh is proven free of crossings with no suspect: each half is
// the graph of a height over the plane.
bool isMirroredHeightField(const TriMesh& mesh, const std::vector<int>& mirror);

}  // namespace rigmesh
