// Rounding the concave corners of a cleaned outline.
//
// An inflated surface rounds a concave outline corner (a crotch, an armpit)
// only with a radius of about z^2 / 2R, far below one edge length, so a
// corner sharper than the mesh can follow becomes a fold from the corner's
// apex into the junction patch above it. Rounding the outline's concave
// corners to a fillet of a couple of edge lengths lets the surface turn
// there in several edges; convex tips are left alone (caps and LSM round
// them in 3D).
#pragma once

#include <limits>

#include "base/Types.h"

namespace rigmesh {

// Moves each vertex of the counter-clockwise closed `polygon` whose concave
// turn is sharper than an arc of radius `radius` (turn over the mean of its
// two edges above 1 / radius) half-way towards the middle of its two
// neighbours, until none is: a curvature flow on the too-sharp concave
// vertices alone, which fills such a corner's apex (the area only grows)
// with an arc of about `radius`. Vertices bunch towards the apex; resample
// afterwards. At most `maxIterations` passes.
Polyline2 roundConcaveCorners(Polyline2 polygon, double radius, int maxIterations = 400,
                              double maxShift = std::numeric_limits<double>::infinity());

// The outline the surface is built on: `polygon` (closed, counter-clockwise,
// about `spacing` apart) with its concave corners rounded to 1.5 spacings,
// the moved points spread evenly along their new path and every other point
// kept exactly; `polygon` itself when it has no such corner or rounding
// would make it cross itself.
Polyline2 surfaceOutline(const Polyline2& polygon, double spacing);

}  // namespace rigmesh
