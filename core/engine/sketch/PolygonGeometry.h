// Basic measures and operations on 2D polylines and closed polygons (a closed
// polygon lists each vertex once; the last connects back to the first).
#pragma once

#include <cstddef>

#include "base/Types.h"

namespace rigmesh {

// The shoelace area of a closed polygon, positive when counter-clockwise.
double signedArea(const Polyline2& polygon);

// Area of the convex hull of `points` (zero for fewer than three).
double convexHullArea(Polyline2 points);

// Diagonal of the axis-aligned bounding box (zero when empty).
double boundingBoxDiagonal(const Polyline2& points);

// Length of the polyline, plus the closing segment when `closed`.
double polylineLength(const Polyline2& points, bool closed);

// The point at arc length `distance` along the open polyline (its last point
// beyond its length).
Vec2 pointAtArcLength(const Polyline2& polyline, double distance);

// `count` points at equal arc-length steps along the closed polygon, starting
// at its first vertex.
Polyline2 resampleClosed(const Polyline2& polygon, std::size_t count);

// The point of the segment ab nearest to p.
Vec2 closestPointOnSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// Distance from p to the segment ab.
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b);

// The signed angle (radians, in (-pi, pi]) from direction `in` to direction
// `out`: positive turning counter-clockwise. At a polygon vertex with edges
// in and out, the turn there.
double turnAngle(const Vec2& in, const Vec2& out);

// Even-odd test: is p inside the closed polygon?
bool insidePolygon(const Polyline2& polygon, const Vec2& p);

// Taubin lambda/mu smoothing of a closed polygon: `iterations` pairs of a
// shrinking and an inflating Laplacian step, which damp jitter without
// shrinking the shape.
Polyline2 taubinSmoothClosed(Polyline2 polygon, int iterations);

}  // namespace rigmesh
