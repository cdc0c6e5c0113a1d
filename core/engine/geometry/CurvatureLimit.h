// Rounding the corners of an open polyline that are sharper than a given
// radius of curvature, leaving every rounder part where it is.
#pragma once

#include <vector>

#include "base/Types.h"

namespace rigmesh {

// Moves the points of every corner whose discrete radius of curvature (turn
// over the mean of its two edges) is below `minRadius`, and their neighbours,
// towards their neighbours' middle until no such corner is left (or after a
// bounded number of rounds). The end points never move.
void limitCurvature(std::vector<Vec2>& points, double minRadius);

}  // namespace rigmesh
