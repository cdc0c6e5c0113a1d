// Body sections near a cylinder's fixed end chord follow the drawn outline.
//
// Paper 2.1 smooths the axis, chords and radii but keeps each body's end
// chords where they are, since a connecting region or a cap shares them.
// Where the outline flares (a thin arm widening into a blob at a concave
// corner) the smoothed sections next to a fixed end lie well inside the
// outline, so the silhouette turns sharply at the end chord's vertex: a
// 39-degree fold. Blending those sections' end points onto the outline,
// mostly next to the end and not at all eight sections in, lets the
// silhouette meet the end chord without a kink.
#pragma once

#include <vector>

#include "axis/Decomposition.h"
#include "surface/CrossSections.h"

namespace rigmesh {

// Moves the end points of the body sections 1 to kSnapReach - 1 in from
// each end chord (at most half-way along the body) towards the nearest
// point of the outline (`regions`' polygon) along the body's side from that
// chord's end point, by 1 - j / kSnapReach for the j-th section in; a
// section that would then cross or crowd a neighbour stays as it was.
// Section counts, polygon indices and cap slices are unchanged; axis
// positions are left as they were (the centres move by a fraction of a
// spacing).
void snapSectionsNearEndsToOutline(std::vector<CylinderSections>& cylinders,
                                   const Decomposition& regions);

}  // namespace rigmesh
