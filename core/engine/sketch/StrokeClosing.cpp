#include "sketch/StrokeClosing.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "sketch/PolygonGeometry.h"
#include "sketch/SegmentCrossings.h"

namespace rigmesh {

namespace {

// The most of the stroke's length that cutting at a crossing of its ends may
// remove. A figure eight's smaller loop is longer than this, so a figure eight
// is never mistaken for an overshoot.
constexpr double kMaxOvershoot = 0.3;
// The fraction of the stroke's length at each end examined for a near miss.
constexpr double kNearMissWindow = 0.2;

// A near miss is trimmed only when its closest approach is this much closer
// than the stroke's actual end (so a plain gap is left alone)...
constexpr double kNearMissRatio = 0.5;
// ...and within this fraction of the stroke's size.
constexpr double kNearMissDistance = 0.1;

struct Windows {
    std::size_t headEnd;    // segments [0, headEnd) form the head
    std::size_t tailBegin;  // segments [tailBegin, count) form the tail
};

Windows endWindows(const Polyline2& stroke, double fraction) {
    const std::size_t segments = stroke.size() - 1;
    const double length = polylineLength(stroke, false);
    Windows windows{0, segments};
    double travelled = 0.0;
    while (windows.headEnd < segments && travelled < fraction * length) {
        travelled += (stroke[windows.headEnd + 1] - stroke[windows.headEnd]).norm();
        ++windows.headEnd;
    }
    travelled = 0.0;
    while (windows.tailBegin > windows.headEnd && travelled < fraction * length) {
        --windows.tailBegin;
        travelled += (stroke[windows.tailBegin + 1] - stroke[windows.tailBegin]).norm();
    }
    return windows;
}

// Cuts at a crossing of a head segment with a tail segment that removes at
// most kMaxOvershoot of the stroke. Taking the latest such head segment and
// then the earliest tail segment leaves no other such crossing inside the kept
// loop.
std::optional<Polyline2> cutAtEndCrossing(const Polyline2& stroke) {
    const Windows windows = endWindows(stroke, kMaxOvershoot);
    std::vector<double> arc{0.0};
    for (std::size_t i = 1; i < stroke.size(); ++i) {
        arc.push_back(arc.back() + (stroke[i] - stroke[i - 1]).norm());
    }
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
    const SegmentCrossing* best = nullptr;
    for (const SegmentCrossing& c : crossings) {
        const std::size_t head = strokeIndex(c.first);
        const std::size_t tail = strokeIndex(c.second);
        const double removed = arc[head] + (c.point - stroke[head]).norm() +
                               (arc.back() - arc[tail] - (c.point - stroke[tail]).norm());
        if (removed > kMaxOvershoot * arc.back()) {
            continue;
        }
        if (best == nullptr || c.first > best->first ||
            (c.first == best->first && c.second < best->second)) {
            best = &c;
        }
    }
    if (best == nullptr) {
        return std::nullopt;
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
    Windows windows = endWindows(stroke, kNearMissWindow);
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
    windows = endWindows(stroke, kNearMissWindow);
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
    if (auto loop = cutAtEndCrossing(stroke)) {
        return *loop;
    }
    return trimNearMisses(stroke);
}

bool returnsToStart(const Polyline2& stroke) {
    Polyline2 distinct;
    for (const Vec2& p : stroke) {
        if (distinct.empty() || p != distinct.back()) {
            distinct.push_back(p);
        }
    }
    if (distinct.size() < 4) {
        return false;
    }
    const Polyline2 closed = closeStroke(distinct);
    const double gap = (closed.back() - closed.front()).norm();
    return gap <= kNearMissDistance * boundingBoxDiagonal(distinct);
}

}  // namespace rigmesh
