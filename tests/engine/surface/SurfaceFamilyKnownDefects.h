// KNOWN DEFECTS of the surface on the generated creature family
// (SurfaceFamilyTest.cpp, tests/support/CreatureOutlines.h): the outlines
// that miss a figure today, each with the figures it reaches (rounded up to
// a tenth; 0 where it meets the limit). These are failures of the surface,
// not accepted results. 2 of the 200 miss a figure (142 before folds were
// relaxed, surface/FoldRelaxation.h; 11 before the outline vertices around
// a fold left at the outline, a slot's apex or a hair-thin tip, were let
// move in the sketch plane): stubs 22 and 35, by a wall (SurfaceWall.h): a
// pleat of steep faces inside the outline in a cap that took in a big
// round lobe whole (Teddy's circle test), where the cap's base chord is
// tilted against the lobe and the slices that would cross it were dropped;
// the strip across that gap fans from the small base ring to a tall slice.
// Least-Squares Meshes now leaves that strip free (surface/SectionGaps.h):
// 4.1 -> 2.2 and 3.9 -> 2.6 spacings, still above 2. Pairing the cap's
// sides otherwise (by a blend with their heights over the base chord, or
// holding one side's end point back where a slice would cross) left the
// walls as they were or made them worse (stubs 22: 2.18 or 2.50, stubs
// 35: 2.81 or 3.81 spacings; docs/ARCHITECTURE.md, section 10). p99, IoU, the
// silhouette and the bulge hold on all. The test
// holds each listed outline to its recorded figures (none may get worse)
// and every other outline to the limits.
#pragma once

#include <array>

#include "CreatureOutlines.h"

namespace rigmesh {

struct KnownDefect {
    testsupport::CreatureClass shapeClass;
    int seed;
    double p99;     // degrees between neighbouring face normals, 99th percentile
    double max;     // degrees, largest
    double shaved;  // outline spacings of the outline left outside the silhouette
    double wall;    // outline spacings inside the outline of a steep face (SurfaceWall.h)
};

using testsupport::CreatureClass;

// clang-format off
inline constexpr KnownDefect kKnownDefects[] = {
    {CreatureClass::Stubs, 22, 0.0, 0.0, 0.0, 2.2},
    {CreatureClass::Stubs, 35, 0.0, 0.0, 0.0, 2.6},
};
// clang-format on

}  // namespace rigmesh
