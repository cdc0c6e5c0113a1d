#include "sketch/ThinPartRefinement.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "geometry/CatmullRom.h"
#include "sketch/SegmentCrossings.h"

namespace rigmesh {
namespace {

// Points closer than this many spacings across are refined.
constexpr double kThinWidths = 3.0;
// Refined pieces are this fraction of the local width, but no shorter than
// kFinestFraction of the spacing (a hair-thin limb cannot ask for unbounded
// points).
constexpr double kPieceOfWidth = 1.0 / 3.0;
constexpr double kFinestFraction = 1.0 / 8.0;

// Does polygon[to] lie left of the outline's tangent at polygon[from]?
bool facesInward(const std::vector<Vec2>& polygon, int from, int to) {
    const int n = static_cast<int>(polygon.size());
    const Vec2 tangent = polygon[(from + 1) % n] - polygon[(from - 1 + n) % n];
    const Vec2 d = polygon[to] - polygon[from];
    return tangent.x() * d.y() - tangent.y() * d.x() > 0;
}

}  // namespace

std::vector<double> outlineWidths(const std::vector<Vec2>& polygon, double limit) {
    const int n = static_cast<int>(polygon.size());
    std::vector<double> arc(n + 1, 0.0);
    for (int i = 0; i < n; ++i)
        arc[i + 1] = arc[i] + (polygon[(i + 1) % n] - polygon[i]).norm();
    const double perimeter = arc[n];
    std::vector<double> width(n, limit);
    if (n == 0 || !(limit > 0))
        return width;
    // Only pairs closer than `limit` matter: bucket the points in a grid of
    // that cell size and compare each with its own and the next cells.
    std::map<std::pair<long, long>, std::vector<int>> cells;
    auto cellOf = [&](const Vec2& p) {
        return std::pair<long, long>{static_cast<long>(std::floor(p.x() / limit)),
                                     static_cast<long>(std::floor(p.y() / limit))};
    };
    for (int i = 0; i < n; ++i)
        cells[cellOf(polygon[i])].push_back(i);
    for (int i = 0; i < n; ++i) {
        const auto [cx, cy] = cellOf(polygon[i]);
        for (long dx = -1; dx <= 1; ++dx)
            for (long dy = -1; dy <= 1; ++dy) {
                const auto found = cells.find({cx + dx, cy + dy});
                if (found == cells.end())
                    continue;
                for (int j : found->second) {
                    const double d = (polygon[i] - polygon[j]).norm();
                    if (j == i || d >= width[i])
                        continue;
                    const double along = std::abs(arc[j] - arc[i]);
                    if (std::min(along, perimeter - along) < 2.0 * d)
                        continue;  // a neighbour along the outline, not across it
                    // Across a limb, not across a gap between two (a crotch
                    // is no thin part; refining it would move the
                    // junction's chords and with them the skeleton): the
                    // other point lies on the inner side (left, as the
                    // outline runs counter-clockwise) of each one's tangent.
                    if (!facesInward(polygon, i, j) || !facesInward(polygon, j, i))
                        continue;
                    width[i] = d;
                }
            }
    }
    // The round end of a limb has no point across it within the 2:1 test
    // (its far side is reached around the end): its width follows its
    // neighbours', growing by half the distance along the outline. Two
    // sweeps each way cover the wrap-around.
    for (int sweep = 0; sweep < 2; ++sweep) {
        for (int i = 0; i < n; ++i) {
            const int previous = (i - 1 + n) % n;
            width[i] =
                std::min(width[i], width[previous] + 0.5 * (polygon[i] - polygon[previous]).norm());
        }
        for (int i = n - 1; i >= 0; --i) {
            const int next = (i + 1) % n;
            width[i] = std::min(width[i], width[next] + 0.5 * (polygon[next] - polygon[i]).norm());
        }
    }
    return width;
}

std::vector<Vec2> refineThinParts(const std::vector<Vec2>& polygon, double spacing) {
    const int n = static_cast<int>(polygon.size());
    if (n < 4 || !(spacing > 0))
        return polygon;
    const std::vector<double> width = outlineWidths(polygon, kThinWidths * spacing);
    std::vector<Vec2> refined;
    bool changed = false;
    for (int i = 0; i < n; ++i) {
        const Vec2& p0 = polygon[(i - 1 + n) % n];
        const Vec2& p1 = polygon[i];
        const Vec2& p2 = polygon[(i + 1) % n];
        const Vec2& p3 = polygon[(i + 2) % n];
        refined.push_back(p1);
        const double local = std::min(width[i], width[(i + 1) % n]);
        if (local >= kThinWidths * spacing)
            continue;
        const double piece = std::max(kPieceOfWidth * local, kFinestFraction * spacing);
        const int pieces = static_cast<int>(std::ceil((p2 - p1).norm() / piece - 0.25));
        for (int k = 1; k < pieces; ++k) {
            refined.push_back(centripetalCatmullRom(p0, p1, p2, p3, double(k) / pieces));
            changed = true;
        }
    }
    if (!changed || crossesItself(refined))
        return polygon;
    return refined;
}

}  // namespace rigmesh
