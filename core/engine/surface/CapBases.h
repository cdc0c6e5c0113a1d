// Where a cylinder's cap begins (paper 2.2): at its end chord, unless that
// chord lies askew across the limb or ends at a corner of the outline.
#pragma once

#include "axis/Decomposition.h"

namespace rigmesh {

// The cylinder with the askew chords at its capped ends handed to the caps:
// a capped end's chord that lies more than a few degrees off the
// perpendicular of the axis (the triangulation's chords zigzag, and the last
// one may be the skew one) is replaced by the least askew of the next few,
// and one ending at a sharp outline corner by the first past the corner;
// the cap's outline path takes in the points between. Connecting ends and
// short cylinders are returned unchanged.
CylinderRegion withCapBases(const Decomposition& decomposition, int cylinder);

}  // namespace rigmesh
