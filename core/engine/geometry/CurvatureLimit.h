// A curvature flow that rounds a polyline's corners sharper than a given
// radius, leaving every rounder part where it is: a cap's outline path
// (surface/CrossSections) and the outline's concave corners
// (sketch/ConcaveCorners) both use it.
#pragma once

#include <limits>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct CurvatureFlow {
    bool closed = false;       // a closed polygon; else the end points never move
    bool concaveOnly = false;  // only clockwise turns (concave on a counter-clockwise polygon)
    int neighbourhood = 0;     // points on either side of a sharp one that move with it
    // No point moves further than this from where it started (it stays put).
    double maxShift = std::numeric_limits<double>::infinity();
    int maxRounds = 400;
};

// Moves each point whose turn over the mean of its two edges is above
// 1 / `minRadius` (a corner sharper than an arc of that radius), and its
// `flow.neighbourhood` neighbours, half-way towards the middle of their two
// neighbours, round after round until no point moves. Points bunch towards
// a rounded apex; resample afterwards where spacing matters.
void limitCurvature(std::vector<Vec2>& points, double minRadius, const CurvatureFlow& flow = {});

}  // namespace rigmesh
