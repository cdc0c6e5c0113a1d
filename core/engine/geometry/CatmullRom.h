// Centripetal Catmull-Rom interpolation (Yuksel, Schaefer and Keyser 2011):
// a C1 curve through polygon points with knots spaced by the square root of
// the distances, so uneven spacing gives no cusps or self-loops.
#pragma once

#include "base/Types.h"

namespace rigmesh {

// The point at `fraction` (0 at p1, 1 at p2) of the segment from p1 to p2 of
// the spline through p0, p1, p2, p3.
Vec2 centripetalCatmullRom(const Vec2& p0, const Vec2& p1, const Vec2& p2, const Vec2& p3,
                           double fraction);

}  // namespace rigmesh
