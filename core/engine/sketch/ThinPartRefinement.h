// Outline resolution follows thickness. The cleaned outline is
// sampled at one spacing everywhere, so a limb about one spacing across ends
// in two or three outline points: its tip is a coarse polygon whose corners
// become creases, however finely the surface then slices it. Where the
// outline is thin, its edges are split along a centripetal Catmull-Rom
// spline through the outline points (geometry/CatmullRom.h), to about a
// third of the local width, so tips are round and the CDT's chords follow
// the limb. Wide parts keep their points; every original point is kept.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

// The width of the outline at each point: the distance to the nearest point
// across the shape (one reached by the outline only along a path at least
// twice as long as the straight line, and on the inner side of the outline
// at both ends),
// at most `limit`, and at most a
// neighbour's width plus half the distance to it (so the round end of a
// thin limb counts as thin).
std::vector<double> outlineWidths(const std::vector<Vec2>& polygon, double limit);

// `polygon` (closed, counter-clockwise, about `spacing` apart) with its thin
// stretches refined; unchanged when that would make it cross itself.
std::vector<Vec2> refineThinParts(const std::vector<Vec2>& polygon, double spacing);

}  // namespace rigmesh
