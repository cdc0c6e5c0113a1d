// Detail levels for export: a part's surface made finer
// or coarser while its rig stays as it is. Skin weights travel with the
// vertices as vertex properties and come out non-negative, summing to 1
// (tiny ones dropped, the rest renormalised). Per-vertex bookkeeping of a
// fresh sketch (origins, mirror map, known closest bones) means nothing on
// the new vertices and is left empty. Both return a part that passes
// Part::validate(), or throw Error with the reason.
#pragma once

#include "part/Part.h"

namespace rigmesh {

// `levels` rounds of Loop subdivision (Loop 1987): every triangle becomes
// four; a new edge vertex is 3/8 of each end plus 1/8 of each opposite
// vertex (the midpoint on an open edge), an old vertex moves to (1 - n b) of
// itself plus b of each of its n neighbours (b = 3/16 for n = 3, else
// 3/(8n); kept on open edges). Weights follow the same stencils. Levels
// 0..4; the result may hold at most kMaxDetailVertices vertices.
Part subdividedPart(const Part& part, int levels);

// Quadric-error decimation (Garland and Heckbert 1997, CGAL's
// Surface_mesh_simplification) down to at most `faces` triangles by
// collapsing edges onto one of their vertices, so every vertex left is an
// original vertex and keeps its own weights exactly. A closed manifold
// surface stays closed and manifold. `faces` at least 4; a part already at
// or below it comes back unchanged.
Part decimatedPart(const Part& part, int faces);

inline constexpr int kMaxDetailVertices = 2'000'000;

}  // namespace rigmesh
