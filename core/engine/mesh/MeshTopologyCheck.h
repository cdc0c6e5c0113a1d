// The topology half of analyseMesh (mesh/MeshChecks.h) on its own: what a
// closed-solid check needs (Part::validateSolid), without the geometry.
#pragma once

#include "mesh/MeshChecks.h"

namespace rigmesh {

// The topology alone (boundary, non-manifold and mis-oriented edges,
// non-manifold vertices, components, Euler characteristic, genus), as
// analyseMesh reports it, without the geometry (degenerate faces, angles,
// area and volume are left 0) and without self-intersections (-1). The
// angles take an atan2 per corner: a closed-solid check of a 6k-vertex part
// costs a third of what analyseMesh does. Throws as analyseMesh does.
MeshReport analyseMeshTopology(const TriMesh& mesh);

// True when the mesh has a face, every face has three distinct corners in
// range, every directed edge occurs once with its reverse once, and the
// faces around each used vertex form one fan: a closed, manifold,
// consistently oriented surface (what CGAL's Surface_mesh builds as a closed
// one; analyseMeshTopology finds no boundary, non-manifold or mis-oriented
// edge and no non-manifold vertex there). Each vertex's corners in one packed
// array, its fan followed within its own corners (no lookups in other
// vertices' lists): a few times cheaper than analyseMeshTopology.
bool isClosedOrientedManifold(const TriMesh& mesh);

}  // namespace rigmesh
