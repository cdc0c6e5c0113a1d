#include "sketch/StrokeClosing.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "sketch/PolygonGeometry.h"
#include "sketch/SegmentCrossings.h"

namespace rigmesh {

namespace {

// The fraction of the stroke's length at each end examined for overshoot.
// Below 1/4, so a figure eight's crossing never falls in both windows.
constexpr double kEndWindow = 0.2;

// A near miss is trimmed only when its closest approach is this much closer
// than the stroke's actual end (so a plain gap is left alone)...
constexpr double kNearMissRatio = 0.5;
// ...and within this fraction of the stroke's size.
constexpr double kNearMissDistance = 0.1;

struct Windows {
    std::size_t headEnd;    // segments [0, headEnd) form the head
    std::size_t tailBegin;  // segments [tailBegin, count) form the tail
};

Windows endWindows(const Polyline2& stroke) {
    const std::size_t segments = stroke.size() - 1;
    const double length = polylineLength(stroke, false);
    Windows windows{0, segments};
    double travelled = 0.0;
    while (windows.headEnd < segments && travelled < kEndWindow * length) {
        travelled += (stroke[windows.headEnd + 1] - stroke[windows.headEnd]).norm();
        ++windows.headEnd;
    }
    travelled = 0.0;
    while (windows.tailBegin > windows.headEnd && travelled < kEndWindow * length) {
        --windows.tailBegin;
        travelled += (stroke[windows.tailBegin + 1] - stroke[windows.tailBegin]).norm();
    }
    return windows;
}

// Cuts at the crossing of a head segment with a tail segment, if any. Taking
// the latest head segment and then the earliest tail segment leaves no other
// head-tail crossing inside the kept loop.
std::optional<Polyline2> cutAtEndCrossing(const Polyline2& stroke, const Windows& windows) {
    std::vector<Segment2> segments;
    for (std::size_t i = 0; i < windows.headEnd; ++i) {
        segments.push_back({stroke[i], stroke[i + 1]});
    }
    const std::size_t headCount = segments.size();
    for (std::size_t i = windows.tailBegin; i + 1 < stroke.size(); ++i) {
        segments.push_back({stroke[i], stroke[i + 1]});
    }
    const auto strokeIndex = [&](std::size_t local) {
        return local < headCount ? local : windows.tailBegin + (local - headCount);
    };
    const auto crossings = findSegmentCrossings(
        segments,
        [&](std::size_t a, std::size_t b) {
            // Head against tail only, never two neighbours sharing a vertex.
            return a < headCount && b >= headCount && strokeIndex(b) > strokeIndex(a) + 1;
        },
        false);
    if (crossings.empty()) {
        return std::nullopt;
    }
    const SegmentCrossing* best = &crossings.front();
    for (const SegmentCrossing& c : crossings) {
        if (c.first > best->first || (c.first == best->first && c.second < best->second)) {
            best = &c;
        }
    }
    const std::size_t head = strokeIndex(best->first);
    const std::size_t tail = strokeIndex(best->second);
    Polyline2 loop{best->point};
    for (std::size_t i = head + 1; i <= tail; ++i) {
        loop.push_back(stroke[i]);
    }
    return loop;
}

struct ClosestPoint {
    std::size_t segment;  // index of the segment's first vertex
    Vec2 point;
    double distance;
};

ClosestPoint closestOnSegments(const Polyline2& stroke, std::size_t begin, std::size_t end,
                               const Vec2& target) {
    ClosestPoint best{begin, stroke[begin], std::numeric_limits<double>::infinity()};
    for (std::size_t i = begin; i < end; ++i) {
        const Vec2 edge = stroke[i + 1] - stroke[i];
        const double squared = edge.squaredNorm();
        const double t =
            squared > 0.0 ? std::clamp((target - stroke[i]).dot(edge) / squared, 0.0, 1.0) : 0.0;
        const Vec2 point = stroke[i] + t * edge;
        const double distance = (point - target).norm();
        if (distance < best.distance) {
            best = {i, point, distance};
        }
    }
    return best;
}

// Cuts the tail where it passes closest to the start, and then the head where
// it passes closest to the new end, when those are clear near misses.
Polyline2 trimNearMisses(Polyline2 stroke) {
    const double size = boundingBoxDiagonal(stroke);
    Windows windows = endWindows(stroke);
    const ClosestPoint tail =
        closestOnSegments(stroke, windows.tailBegin, stroke.size() - 1, stroke.front());
    const double endGap = (stroke.back() - stroke.front()).norm();
    if (tail.distance <= kNearMissRatio * endGap && tail.distance <= kNearMissDistance * size) {
        stroke.resize(tail.segment + 1);
        if ((tail.point - stroke.back()).norm() > 0.0) {
            stroke.push_back(tail.point);
        }
    }
    if (stroke.size() < 3) {
        return stroke;
    }
    windows = endWindows(stroke);
    const ClosestPoint head = closestOnSegments(stroke, 0, windows.headEnd, stroke.back());
    const double startGap = (stroke.back() - stroke.front()).norm();
    if (head.distance <= kNearMissRatio * startGap && head.distance <= kNearMissDistance * size) {
        Polyline2 trimmed{head.point};
        for (std::size_t i = head.segment + 1; i < stroke.size(); ++i) {
            if ((stroke[i] - trimmed.back()).norm() > 0.0) {
                trimmed.push_back(stroke[i]);
            }
        }
        stroke = std::move(trimmed);
    }
    return stroke;
}

}  // namespace

Polyline2 closeStroke(const Polyline2& stroke) {
    if (stroke.size() < 4) {
        return stroke;
    }
    if (auto loop = cutAtEndCrossing(stroke, endWindows(stroke))) {
        return *loop;
    }
    return trimNearMisses(stroke);
}

}  // namespace rigmesh
