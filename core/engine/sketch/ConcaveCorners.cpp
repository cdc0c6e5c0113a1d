#include "sketch/ConcaveCorners.h"

#include <cmath>

#include "sketch/PolygonGeometry.h"
#include "sketch/SegmentCrossings.h"

namespace rigmesh {

Polyline2 roundConcaveCorners(Polyline2 polygon, double radius, int maxIterations,
                              double maxShift) {
    const long n = static_cast<long>(polygon.size());
    if (n < 4 || !(radius > 0))
        return polygon;
    const Polyline2 original = polygon;
    for (int iteration = 0; iteration < maxIterations; ++iteration) {
        Polyline2 next = polygon;
        bool moved = false;
        for (long i = 0; i < n; ++i) {
            const Vec2& a = polygon[static_cast<std::size_t>((i + n - 1) % n)];
            const Vec2& b = polygon[static_cast<std::size_t>(i)];
            const Vec2& c = polygon[static_cast<std::size_t>((i + 1) % n)];
            const Vec2 in = b - a, out = c - b;
            const double turn =
                std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));  // < 0: concave
            const double length = 0.5 * (in.norm() + out.norm());
            if (turn >= 0 || -turn * radius <= length)
                continue;
            const Vec2 target = 0.5 * b + 0.25 * (a + c);
            if ((target - original[static_cast<std::size_t>(i)]).norm() > maxShift)
                continue;
            next[static_cast<std::size_t>(i)] = target;
            moved = true;
        }
        polygon = std::move(next);
        if (!moved)
            break;
    }
    return polygon;
}

Polyline2 surfaceOutline(const Polyline2& polygon, double spacing) {
    constexpr double kCornerRadius = 1.5;  // spacings
    constexpr double kMaxShift = 1.0;      // spacings: a narrow slot is not filled up
    const Polyline2 moved =
        roundConcaveCorners(polygon, kCornerRadius * spacing, 400, kMaxShift * spacing);
    if (moved == polygon)
        return polygon;
    // The flow bunches the moved points towards each apex: every run of
    // moved points is spread again evenly along its new path, between the
    // unmoved points on either side, which stay exactly where they were.
    const std::size_t n = polygon.size();
    std::size_t start = 0;
    while (start < n && moved[start] != polygon[start])
        ++start;
    if (start == n)
        return polygon;  // every point moved: not a corner
    Polyline2 rounded = moved;
    for (std::size_t k = 1; k <= n; ++k) {
        const std::size_t first = (start + k) % n;
        if (moved[first] == polygon[first])
            continue;
        std::size_t count = 0;
        while (moved[(first + count) % n] != polygon[(first + count) % n])
            ++count;
        Polyline2 path{moved[(first + n - 1) % n]};
        for (std::size_t i = 0; i <= count; ++i)
            path.push_back(moved[(first + i) % n]);
        const double length = polylineLength(path, false);
        for (std::size_t i = 1; i <= count; ++i)
            rounded[(first + i - 1) % n] = pointAtArcLength(
                path, length * static_cast<double>(i) / static_cast<double>(count + 1));
        k += count;
    }
    return crossesItself(rounded) ? polygon : rounded;
}

}  // namespace rigmesh
