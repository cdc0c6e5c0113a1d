// Turning an open hand-drawn stroke into a closed polygon.
#pragma once

#include "base/Types.h"

namespace rigmesh {

// Closes `stroke` (an open polyline without repeated consecutive points):
// when its end overshoots and crosses its beginning, both are cut at the
// crossing; when the end slides past the start without crossing, the
// overshooting parts are cut at their closest approach; a remaining gap is
// closed by the implicit straight segment from the last point to the first.
// A crossing is only cut when that removes at most 30% of the stroke, so a
// figure eight's crossing is left for the caller to reject.
Polyline2 closeStroke(const Polyline2& stroke);

}  // namespace rigmesh
