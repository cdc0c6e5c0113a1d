// Turning an open hand-drawn stroke into a closed polygon.
#pragma once

#include "base/Types.h"

namespace rigmesh {

// Closes `stroke` (an open polyline without repeated consecutive points):
// when its end overshoots and crosses its beginning, both are cut at the
// crossing; when the end slides past the start without crossing, the
// overshooting parts are cut at their closest approach; a remaining gap is
// closed by the implicit straight segment from the last point to the first.
// Only the first and last fifth of the stroke's length are examined, so a
// crossing in the middle (a figure eight) is left for the caller to reject.
Polyline2 closeStroke(const Polyline2& stroke);

}  // namespace rigmesh
