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

// True when a stroke being drawn has come back to its start: its end crosses
// its beginning, or the gap closeStroke leaves between its ends is within the
// near-miss distance (a tenth of the stroke's bounding-box diagonal), the
// tolerance closeStroke trims near misses with. Repeated consecutive points
// are ignored. A live preview waits for this; a finished stroke is closed
// with a straight segment whatever its gap.
bool returnsToStart(const Polyline2& stroke);

}  // namespace rigmesh
