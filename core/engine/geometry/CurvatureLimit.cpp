#include "geometry/CurvatureLimit.h"

#include <algorithm>
#include <cmath>

#include "sketch/PolygonGeometry.h"

namespace rigmesh {

void limitCurvature(std::vector<Vec2>& points, double minRadius, const CurvatureFlow& flow) {
    const int n = static_cast<int>(points.size());
    if (n < 3 || !(minRadius > 0))
        return;
    // Interior points of an open polyline; every point of a closed one.
    const int first = flow.closed ? 0 : 1, last = flow.closed ? n - 1 : n - 2;
    auto at = [&](int i) { return (i % n + n) % n; };
    const std::vector<Vec2> original = points;
    std::vector<char> marked(n);
    for (int round = 0; round < flow.maxRounds; ++round) {
        std::fill(marked.begin(), marked.end(), 0);
        for (int i = first; i <= last; ++i) {
            const Vec2 in = points[i] - points[at(i - 1)], out = points[at(i + 1)] - points[i];
            const double turn = turnAngle(in, out);
            if (flow.concaveOnly && turn >= 0)
                continue;
            if (std::abs(turn) * minRadius <= 0.5 * (in.norm() + out.norm()))
                continue;
            for (int j = i - flow.neighbourhood; j <= i + flow.neighbourhood; ++j)
                if (flow.closed || (j >= first && j <= last))
                    marked[at(j)] = 1;
        }
        // One Laplacian step (lambda 1/2) on the marked points only.
        std::vector<Vec2> next = points;
        bool moved = false;
        for (int i = first; i <= last; ++i) {
            if (!marked[i])
                continue;
            const Vec2 target = 0.5 * points[i] + 0.25 * (points[at(i - 1)] + points[at(i + 1)]);
            if ((target - original[i]).norm() > flow.maxShift)
                continue;
            next[i] = target;
            moved = true;
        }
        points = std::move(next);
        if (!moved)
            return;
    }
}

}  // namespace rigmesh
