// How far a surface's front view strays from its outline: the largest
// distance from a point of the outline left outside the silhouette to the
// silhouette (a limb or bump shaved off) and from a point of the silhouette
// outside the outline to the outline (a bulge), on a raster of about eight
// cells per outline spacing.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "SilhouetteRaster.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh::surfacetest {

struct Deviation {
    double shaved = 0;  // outline outside the silhouette, deepest
    double bulged = 0;  // silhouette outside the outline, farthest
    Vec2 worstShaved = Vec2::Zero();
};

inline Deviation outlineDeviation(const TriMesh& mesh, const std::vector<Vec2>& outline,
                                  double spacing) {
    Eigen::AlignedBox2d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(v.head<2>());
    for (const Vec2& p : outline)
        box.extend(p);
    // Square cells, a margin of a few spacings.
    const double side = box.sizes().maxCoeff() + 6 * spacing;
    const Vec2 centre = box.center();
    const Eigen::AlignedBox2d square(centre - Vec2::Constant(side / 2),
                                     centre + Vec2::Constant(side / 2));
    const int resolution = std::clamp(static_cast<int>(std::ceil(8 * side / spacing)), 64, 2048);
    const double cell = side / resolution;
    SilhouetteGrid grid(square, resolution);
    grid.fillProjection(mesh);
    auto cellOf = [&](const Vec2& p) {
        return Eigen::Vector2i(
            std::clamp(static_cast<int>(std::floor((p.x() - square.min().x()) / cell)), 0,
                       resolution - 1),
            std::clamp(static_cast<int>(std::floor((p.y() - square.min().y()) / cell)), 0,
                       resolution - 1));
    };
    Deviation result;
    // The outline walked at a quarter spacing: each point outside the
    // silhouette, its distance to the nearest filled cell (searched a few
    // spacings around; farther counts as that far).
    const int reach = static_cast<int>(std::ceil(4 * spacing / cell));
    const std::size_t n = outline.size();
    for (std::size_t i = 0; i < n; ++i) {
        const Vec2 &a = outline[i], &b = outline[(i + 1) % n];
        const int pieces = std::max(1, static_cast<int>(std::ceil(4 * (b - a).norm() / spacing)));
        for (int k = 0; k < pieces; ++k) {
            const Vec2 p = a + (b - a) * (double(k) / pieces);
            const Eigen::Vector2i c = cellOf(p);
            if (grid.filled(c.x(), c.y()))
                continue;
            double nearest = (reach + 1) * cell;
            for (int j = std::max(0, c.y() - reach); j <= std::min(resolution - 1, c.y() + reach);
                 ++j)
                for (int i2 = std::max(0, c.x() - reach);
                     i2 <= std::min(resolution - 1, c.x() + reach); ++i2)
                    if (grid.filled(i2, j))
                        nearest = std::min(nearest, (grid.centre(i2, j) - p).norm());
            if (nearest > result.shaved) {
                result.shaved = nearest;
                result.worstShaved = p;
            }
        }
    }
    // Filled cells outside the outline: their distance to it.
    for (int j = 0; j < resolution; ++j)
        for (int i = 0; i < resolution; ++i) {
            if (!grid.filled(i, j))
                continue;
            const Vec2 p = grid.centre(i, j);
            if (insidePolygon(outline, p))
                continue;
            double nearest = std::numeric_limits<double>::infinity();
            for (std::size_t k = 0; k < n; ++k)
                nearest = std::min(nearest, distanceToSegment(p, outline[k], outline[(k + 1) % n]));
            result.bulged = std::max(result.bulged, nearest);
        }
    return result;
}

}  // namespace rigmesh::surfacetest
