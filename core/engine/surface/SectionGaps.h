// Gaps between neighbouring cap slices (after paper 2.2).
//
// A cap's slices stand about one local edge length apart on each side (its
// sides are walked in such steps, CrossSections' sliceCap). Where slices
// were dropped because they would cross the one before (a cap that took in
// a big round lobe whole, its base chord tilted against the lobe, one side
// of the outline running along the slices), the two slices left either
// side of the drop are far apart on one side: the strip between them
// stitches a tall semicircle to the low end of a small one standing inside
// it, a steep wall well inside the outline (stubs of the creature family,
// tests/engine/surface/SurfaceWall.h). Least-Squares Meshes (2.2, Fig. 3f)
// leaves such a strip free, as it does a connecting region, so the step is
// smoothed out instead of held.
#pragma once

#include <vector>

#include "surface/CrossSections.h"

namespace rigmesh {

struct SectionGap {
    double axisPosition = 0.0;  // middle of the two sections along the axis
    double halfWidth = 0.0;     // half their distance along the axis
    double length = 0.0;        // the longer distance between their end points
};

// The gaps of a cylinder: neighbouring sections, one of them a cap slice,
// whose end points on one side lie more than `ratio` times the larger of
// their local edge lengths apart.
std::vector<SectionGap> sectionGaps(const CylinderSections& cylinder, double targetEdgeLength,
                                    double ratio = 3.0);

}  // namespace rigmesh
