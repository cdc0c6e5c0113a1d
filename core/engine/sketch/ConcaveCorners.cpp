#include "sketch/ConcaveCorners.h"

#include <cmath>

#include "geometry/CurvatureLimit.h"
#include "sketch/PolygonGeometry.h"
#include "sketch/SegmentCrossings.h"

namespace rigmesh {

Polyline2 roundConcaveCorners(Polyline2 polygon, double radius, int maxIterations,
                              double maxShift) {
    if (polygon.size() < 4)
        return polygon;
    CurvatureFlow flow;
    flow.closed = true;
    flow.concaveOnly = true;
    flow.maxShift = maxShift;
    flow.maxRounds = maxIterations;
    limitCurvature(polygon, radius, flow);
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
