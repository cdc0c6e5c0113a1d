#include "sketch/SegmentCrossings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace rigmesh {

namespace {

double orientation(const Vec2& a, const Vec2& b, const Vec2& c) {
    return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

// Overlap of collinear segments ab and cd, compared along their longer axis.
bool collinearOverlap(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Vec2& point) {
    const Vec2 extent = (b - a).cwiseAbs() + (d - c).cwiseAbs();
    const int axis = extent.x() >= extent.y() ? 0 : 1;
    const double lowAB = std::min(a[axis], b[axis]);
    const double highAB = std::max(a[axis], b[axis]);
    const double lowCD = std::min(c[axis], d[axis]);
    const double highCD = std::max(c[axis], d[axis]);
    if (highAB < lowCD || highCD < lowAB) {
        return false;
    }
    // Report the endpoint of one segment that lies inside the other.
    for (const Vec2* p : {&c, &d, &a, &b}) {
        const bool inAB = (*p)[axis] >= lowAB && (*p)[axis] <= highAB;
        const bool inCD = (*p)[axis] >= lowCD && (*p)[axis] <= highCD;
        if (inAB && inCD) {
            point = *p;
            return true;
        }
    }
    point = c;
    return true;
}

// Every grid cell a segment passes through, as (cell key, segment index).
class GridRasterizer {
  public:
    GridRasterizer(const Vec2& origin, double cellSize) : origin_(origin), cell_(cellSize) {}

    void add(const Segment2& segment, std::uint32_t index,
             std::vector<std::pair<std::uint64_t, std::uint32_t>>& out) const {
        const Vec2 a = (segment.a - origin_) / cell_;
        const Vec2 b = (segment.b - origin_) / cell_;
        // A small padding makes sure a shared point on a cell border puts both
        // segments in a common cell despite rounding.
        constexpr double pad = 1e-7;
        const double xLow = std::min(a.x(), b.x()) - pad;
        const double xHigh = std::max(a.x(), b.x()) + pad;
        const double dx = b.x() - a.x();
        for (auto column = static_cast<std::int64_t>(std::floor(xLow));
             column <= static_cast<std::int64_t>(std::floor(xHigh)); ++column) {
            // The part of the segment inside this column, as a y range.
            const double x0 = std::max(xLow, static_cast<double>(column));
            const double x1 = std::min(xHigh, static_cast<double>(column + 1));
            double y0 = std::min(a.y(), b.y());
            double y1 = std::max(a.y(), b.y());
            if (std::abs(dx) > 1e-12) {
                const double t0 = std::clamp((x0 - a.x()) / dx, 0.0, 1.0);
                const double t1 = std::clamp((x1 - a.x()) / dx, 0.0, 1.0);
                const double ya = a.y() + t0 * (b.y() - a.y());
                const double yb = a.y() + t1 * (b.y() - a.y());
                y0 = std::min(ya, yb);
                y1 = std::max(ya, yb);
            }
            for (auto row = static_cast<std::int64_t>(std::floor(y0 - pad));
                 row <= static_cast<std::int64_t>(std::floor(y1 + pad)); ++row) {
                out.emplace_back(key(column, row), index);
            }
        }
    }

  private:
    static std::uint64_t key(std::int64_t column, std::int64_t row) {
        return (static_cast<std::uint64_t>(column + 1) << 32) | static_cast<std::uint32_t>(row + 1);
    }

    Vec2 origin_;
    double cell_;
};

}  // namespace

bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d, Vec2& point) {
    // Disjoint bounding boxes settle most pairs, and also keep rounding noise
    // from making far-apart collinear segments look like they cross.
    if (std::max(a.x(), b.x()) < std::min(c.x(), d.x()) ||
        std::max(c.x(), d.x()) < std::min(a.x(), b.x()) ||
        std::max(a.y(), b.y()) < std::min(c.y(), d.y()) ||
        std::max(c.y(), d.y()) < std::min(a.y(), b.y())) {
        return false;
    }
    const double o1 = orientation(a, b, c);
    const double o2 = orientation(a, b, d);
    if (o1 == 0.0 && o2 == 0.0) {
        return collinearOverlap(a, b, c, d, point);
    }
    if ((o1 > 0.0 && o2 > 0.0) || (o1 < 0.0 && o2 < 0.0)) {
        return false;
    }
    const double o3 = orientation(c, d, a);
    const double o4 = orientation(c, d, b);
    if ((o3 > 0.0 && o4 > 0.0) || (o3 < 0.0 && o4 < 0.0)) {
        return false;
    }
    // The line through cd divides ab at the ratio of their signed distances.
    const double t = o3 == o4 ? 0.0 : o3 / (o3 - o4);
    point = a + std::clamp(t, 0.0, 1.0) * (b - a);
    return true;
}

std::vector<SegmentCrossing> findSegmentCrossings(
    const std::vector<Segment2>& segments,
    const std::function<bool(std::size_t, std::size_t)>& consider, bool firstOnly) {
    std::vector<SegmentCrossing> crossings;
    if (segments.size() < 2) {
        return crossings;
    }
    Vec2 low = segments.front().a;
    Vec2 high = low;
    double totalLength = 0.0;
    for (const Segment2& s : segments) {
        low = low.cwiseMin(s.a).cwiseMin(s.b);
        high = high.cwiseMax(s.a).cwiseMax(s.b);
        totalLength += (s.b - s.a).norm();
    }
    // Cells about as large as an average segment keep both the number of cells
    // per segment and the number of segments per cell small.
    const double extent = (high - low).maxCoeff();
    double cellSize = totalLength / static_cast<double>(segments.size());
    cellSize = std::max({cellSize, extent / 1e7, 1e-300});
    if (extent == 0.0) {
        cellSize = 1.0;
    }
    const GridRasterizer grid(low, cellSize);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    entries.reserve(segments.size() * 4);
    for (std::size_t i = 0; i < segments.size(); ++i) {
        grid.add(segments[i], static_cast<std::uint32_t>(i), entries);
    }
    std::sort(entries.begin(), entries.end());

    for (std::size_t begin = 0; begin < entries.size();) {
        std::size_t end = begin;
        while (end < entries.size() && entries[end].first == entries[begin].first) {
            ++end;
        }
        for (std::size_t p = begin; p < end; ++p) {
            for (std::size_t q = p + 1; q < end; ++q) {
                const std::size_t i = entries[p].second;
                const std::size_t j = entries[q].second;
                if (!consider(i, j)) {
                    continue;
                }
                const Segment2& s = segments[i];
                const Segment2& t = segments[j];
                Vec2 point;
                if (segmentsIntersect(s.a, s.b, t.a, t.b, point)) {
                    crossings.push_back({i, j, point});
                    if (firstOnly) {
                        return crossings;
                    }
                }
            }
        }
        begin = end;
    }
    // The same pair can meet in several cells: keep one report per pair.
    std::sort(crossings.begin(), crossings.end(), [](const auto& x, const auto& y) {
        return std::pair(x.first, x.second) < std::pair(y.first, y.second);
    });
    crossings.erase(std::unique(crossings.begin(), crossings.end(),
                                [](const auto& x, const auto& y) {
                                    return x.first == y.first && x.second == y.second;
                                }),
                    crossings.end());
    return crossings;
}

bool crossesItself(const std::vector<Vec2>& polygon) {
    const std::size_t n = polygon.size();
    std::vector<Segment2> segments;
    for (std::size_t i = 0; i < n; ++i)
        segments.push_back({polygon[i], polygon[(i + 1) % n]});
    auto notAdjacent = [n](std::size_t i, std::size_t j) {
        return j != i + 1 && !(i == 0 && j == n - 1);
    };
    return !findSegmentCrossings(segments, notAdjacent, true).empty();
}

}  // namespace rigmesh
