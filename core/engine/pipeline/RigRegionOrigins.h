// The skeleton does not see pruned bumps (paper 2.1 prunes them as
// insignificant branches), while the surface must cover them.
// sketchToSurface therefore decomposes twice: with body bumps as connecting
// regions for the surface (axis/BodyBumps.h), and without for the rig, whose
// skeleton, joint ids and recipes stay what they were. The vertex origins
// are then told in the rig's regions: a body piece's ring belongs to the rig
// cylinder the piece came from, at the cross section nearest the ring's
// centre, and a bump patch's vertex at the section nearest itself, as if
// that cylinder had been built over the bump.
#pragma once

#include <vector>

#include "surface/SketchSurface.h"

namespace rigmesh {

// True when `surface` and `rig` decompose the sketch into the same regions.
bool sameRegions(const Decomposition& surface, const Decomposition& rig);

// Rewrites `surface.origins` from the regions of `surfaceRegions` to those
// of `rigRegions`.
void mapOriginsToRigRegions(SketchSurface& surface, const Decomposition& surfaceRegions,
                            const std::vector<CylinderSections>& surfaceCylinders,
                            const Decomposition& rigRegions,
                            const std::vector<CylinderSections>& rigCylinders);

// As above when the surface was built on another outline than the rig's
// (concave corners rounded, sketch/ConcaveCorners.h), so no chord is shared:
// a ring belongs to the rig section nearest its centre over all cylinders,
// a tip to the nearest rig section or tip, a patch vertex to the rig's
// connecting region with the nearest junction (or, without one, to the
// nearest section); a vertex of a patch with no junction of its own (a cap
// built as a patch, surface/CapPatches.h) to the nearest section or tip.
void mapOriginsByNearestSection(SketchSurface& surface, const Decomposition& surfaceRegions,
                                const std::vector<CylinderSections>& surfaceCylinders,
                                const Decomposition& rigRegions,
                                const std::vector<CylinderSections>& rigCylinders);

}  // namespace rigmesh
