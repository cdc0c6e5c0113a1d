#include "surface/PatchLattice.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "base/Error.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

// Boundary segments bucketed in square cells one edge length wide: a segment
// within half an edge of a point touches the point's cell or a neighbour.
class SegmentGrid {
  public:
    SegmentGrid(const std::vector<Vec2>& loop, const Eigen::AlignedBox2d& box, double cell)
        : loop_(loop),
          origin_(box.min()),
          cell_(cell),
          columns_(cellCount(box.sizes().x())),
          rows_(cellCount(box.sizes().y())),
          cells_(static_cast<std::size_t>(columns_) * static_cast<std::size_t>(rows_)) {
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const Vec2& a = loop[i];
            const Vec2& b = loop[(i + 1) % loop.size()];
            // Long segments are walked in pieces of one cell, so each marks
            // only the cells along it.
            const int pieces = std::max(1, static_cast<int>(std::ceil((b - a).norm() / cell)));
            for (int k = 0; k < pieces; ++k) {
                Eigen::AlignedBox2d piece(a + (b - a) * (double(k) / pieces));
                piece.extend(a + (b - a) * (double(k + 1) / pieces));
                for (int r = row(piece.min().y()); r <= row(piece.max().y()); ++r)
                    for (int c = column(piece.min().x()); c <= column(piece.max().x()); ++c) {
                        auto& bucket = cells_[index(c, r)];
                        if (bucket.empty() || bucket.back() != static_cast<int>(i))
                            bucket.push_back(static_cast<int>(i));
                    }
            }
        }
    }

    // Distance to the nearest segment, or infinity when none lies in the 3 x 3 cells around.
    double nearbyClearance(const Vec2& p) const {
        double clearance = std::numeric_limits<double>::infinity();
        const int c0 = column(p.x()), r0 = row(p.y());
        for (int r = std::max(0, r0 - 1); r <= std::min(rows_ - 1, r0 + 1); ++r)
            for (int c = std::max(0, c0 - 1); c <= std::min(columns_ - 1, c0 + 1); ++c)
                for (int i : cells_[index(c, r)])
                    clearance = std::min(
                        clearance, distanceToSegment(p, loop_[i], loop_[(i + 1) % loop_.size()]));
        return clearance;
    }

  private:
    int cellCount(double extent) const {
        return std::max(1, static_cast<int>(std::floor(extent / cell_)) + 1);
    }
    int column(double x) const {
        return std::clamp(static_cast<int>(std::floor((x - origin_.x()) / cell_)), 0, columns_ - 1);
    }
    int row(double y) const {
        return std::clamp(static_cast<int>(std::floor((y - origin_.y()) / cell_)), 0, rows_ - 1);
    }
    std::size_t index(int c, int r) const {
        return static_cast<std::size_t>(r) * static_cast<std::size_t>(columns_) +
               static_cast<std::size_t>(c);
    }

    const std::vector<Vec2>& loop_;
    Vec2 origin_;
    double cell_;
    int columns_, rows_;
    std::vector<std::vector<int>> cells_;
};

// A lattice box of more points than this cannot come from an outline the
// pipeline accepts (its vertex budget); it means an edge length the caller
// did not check.
constexpr double kMaxLatticePoints = 5e7;

int stepCount(double extent, double step) {
    const double count = std::ceil(extent / step);
    if (!(count <= kMaxLatticePoints))
        throw Error(MessageId::PatchTooManyRows, std::to_string(count));
    return static_cast<int>(count);
}

}  // namespace

std::vector<Vec2> latticeInside(const std::vector<Vec2>& boundary, double edgeLength) {
    const double h = edgeLength;
    Eigen::AlignedBox2d box;
    for (const Vec2& p : boundary)
        box.extend(p);
    const double rowHeight = h * std::sqrt(3.0) / 2.0;
    const int rows = stepCount(box.sizes().y(), rowHeight);
    const int columns = stepCount(box.sizes().x(), h);
    if (!(double(rows + 1) * double(columns + 1) <= kMaxLatticePoints))
        throw Error(MessageId::PatchTooManyPoints,
                    std::to_string(double(rows + 1) * double(columns + 1)));
    const SegmentGrid grid(boundary, box, h);
    std::vector<Vec2> points;
    for (int row = 0; row < rows; ++row) {
        const double y = box.min().y() + (row + 0.5) * rowHeight;
        if (!(y < box.max().y()))
            break;
        for (int column = 0; column <= columns; ++column) {
            const double x = box.min().x() + (column + (row % 2 ? 0.5 : 0.0)) * h;
            if (!(x < box.max().x()))
                break;
            const Vec2 p(x, y);
            if (grid.nearbyClearance(p) > 0.5 * h)
                points.push_back(p);
        }
    }
    return points;
}

}  // namespace rigmesh
