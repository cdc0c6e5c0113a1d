// Flattening of SVG path data (the `d` attribute) into a polyline.
#pragma once

#include <string_view>

#include "base/Types.h"

namespace rigmesh {

// Returns the points of the first subpath of `pathData`, in the path's own
// coordinates (SVG y-down). Lines contribute their end points; every Bézier
// segment contributes `curveSamples` points and every elliptical arc about
// `curveSamples` points per quarter turn. A closing Z adds no point. Throws
// SvgSyntaxError (sketch/SvgNumberScanner.h) on malformed data.
Polyline2 flattenSvgPathData(std::string_view pathData, int curveSamples = 16);

}  // namespace rigmesh
