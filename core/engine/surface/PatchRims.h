// Round rims for connecting patches. The paper leaves connecting
// regions free in Least-Squares Meshes (2.2), since they "typically share
// only a short boundary with the user sketch". Where a patch does follow the
// outline for long (a rump, a bump off a body, a blob between limbs), a free
// patch held at z = 0 on the outline meets its mirror image at an angle: a
// fold along the silhouette. Near the outline the patch's vertices are
// therefore lifted to an inflated height, sqrt(d (2R - d)) at distance d
// from the outline for the region's thickness R (how far its inside reaches
// from the outline), and held there softly, less so further in and not
// within a port's radius of its ring, so the surface meets the sketch plane
// upright as a round cylinder does. Distances are measured along the
// patch's edges from its boundary (linear in its vertices).
#pragma once

#include <vector>

#include "surface/SketchSurface.h"

namespace rigmesh {

// Lifts the connecting regions' vertices (and their mirror images) and
// returns their soft anchor weights, at most `rimWeight`, falling to 0 at
// distance R; other vertices get 0. A region with no junction triangle (a
// cap built as a patch, CapPatches.h) is held up to `capPatchWeight`: no
// junction's rings shape it, so its lift is the lobe's whole shape.
std::vector<double> inflatePatchRims(SketchSurface& surface, const Decomposition& decomposition,
                                     const std::vector<CylinderSections>& cylinders,
                                     double rimWeight, double capPatchWeight);

}  // namespace rigmesh
