#include "geometry/CurvatureLimit.h"

#include <algorithm>
#include <cmath>

namespace rigmesh {
namespace {

// Enough for a right-angled corner sampled at a fifth of the radius asked
// (the test's case; cap paths are sampled at a sixth).
constexpr int kMaxRounds = 400;
// How many points on either side of a sharp one move with it, so that the
// turn spreads instead of moving to the next point.
constexpr int kNeighbourhood = 2;

double curvatureAt(const std::vector<Vec2>& points, int i) {
    const Vec2 a = points[i] - points[i - 1], b = points[i + 1] - points[i];
    const double turn = std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
    return turn / std::max(1e-12, 0.5 * (a.norm() + b.norm()));
}

}  // namespace

void limitCurvature(std::vector<Vec2>& points, double minRadius) {
    const int n = static_cast<int>(points.size());
    if (n < 3 || !(minRadius > 0))
        return;
    std::vector<char> moves(n);
    for (int round = 0; round < kMaxRounds; ++round) {
        std::fill(moves.begin(), moves.end(), 0);
        bool any = false;
        for (int i = 1; i + 1 < n; ++i) {
            if (curvatureAt(points, i) * minRadius <= 1.0)
                continue;
            any = true;
            for (int j = std::max(1, i - kNeighbourhood); j <= std::min(n - 2, i + kNeighbourhood);
                 ++j)
                moves[j] = 1;
        }
        if (!any)
            return;
        // One Laplacian step (lambda 1/2) on the marked points only.
        std::vector<Vec2> previous = points;
        for (int i = 1; i + 1 < n; ++i)
            if (moves[i])
                points[i] = 0.5 * previous[i] + 0.25 * (previous[i - 1] + previous[i + 1]);
    }
}

}  // namespace rigmesh
