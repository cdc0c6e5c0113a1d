// Caps whose slices cannot follow their outline, built as patches instead
// (after paper 2.2).
//
// A cap is sliced by walking both sides of its outline in equal steps
// (CrossSections' sliceCap). Where a cap takes in a big round lobe whole
// (Teddy's circle test, 2.1) and one side of its outline runs along the
// slices beyond a concave corner beside the cap's base (a short limb
// rising off the lobe next to the limb the cap ends), the slices ending on
// that side would cross the one before and are dropped; every straight
// slice ending on the flank beyond the corner passes the corner on the
// inside, so the semicircles stand tall a spacing or two from an outline
// point of height zero: a wall inside the outline (creature family,
// tests/engine/surface/SurfaceWall.h). Such a cap is built as a connecting
// region with the limb's last section as its one port: its patch is lifted
// by its distance to the outline (surface/PatchRims.h), which rounds a
// concave corner as an inflation does, and rises from the port's ring at
// 45 degrees to the lobe's own thickness.
#pragma once

#include <vector>

#include "surface/CrossSections.h"

namespace rigmesh {

// Turns every cap of `regions` whose slices leave a gap (SectionGaps.h: a
// slice dropped where it would cross the one before) and would stand as a
// wall more than 4 local edge lengths inside the outline (a slice's
// semicircle steeper over its distance to a concave corner than
// SurfaceWall.h's 75 degrees) into a connecting region with that
// cylinder's end section as its one port, and rebuilds that cylinder's
// sections in `cylinders`. Returns whether any cap was turned.
bool patchCapsWithGaps(Decomposition& regions, std::vector<CylinderSections>& cylinders,
                       double targetEdgeLength, const CrossSectionOptions& options);

}  // namespace rigmesh
