// splitBySurface (cut/SurfaceSplit.h) from the input's CGAL surface, for a
// caller that has built it already (cut/CutPart builds it first: a closed
// surface built directly also says the part is closed, oriented and
// manifold). Include only from .cpp files: it brings in CGAL
// (mesh/CgalSurfaceMesh.h).
#pragma once

#include <vector>

#include "cut/SurfaceSplit.h"
#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

// `surface`: `mesh` as mesh/CgalClosedSurface's closedSurfaceMesh or
// mesh/CgalSurfaceMesh's toSurfaceMesh builds it (the same elements).
std::vector<MeshPiece> splitBySurface(const TriMesh& mesh, cgal::SurfaceMesh surface,
                                      const CutSurface& surfaceToCut,
                                      SplitMethod method = SplitMethod::Band,
                                      SplitReport* report = nullptr);

}  // namespace rigmesh
