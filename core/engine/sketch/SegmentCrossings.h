// Finding pairs of 2D segments that cross or touch, with a uniform grid so
// that a polygon of n segments of similar length costs about O(n).
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct Segment2 {
    Vec2 a;
    Vec2 b;
};

struct SegmentCrossing {
    std::size_t first;   // the smaller segment index
    std::size_t second;  // the larger segment index
    Vec2 point;          // a point the two segments share
};

// True when segments ab and cd share a point (crossing, touching or
// overlapping); `point` then receives one such point.
bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Vec2& point);

// The intersecting pairs (i < j) among `segments` for which `consider(i, j)`
// is true, sorted by (first, second). With `firstOnly` the search stops at the
// first pair found.
std::vector<SegmentCrossing> findSegmentCrossings(
    const std::vector<Segment2>& segments,
    const std::function<bool(std::size_t, std::size_t)>& consider, bool firstOnly);

// True when two non-adjacent edges of the closed polygon share a point.
bool crossesItself(const std::vector<Vec2>& polygon);

}  // namespace rigmesh
