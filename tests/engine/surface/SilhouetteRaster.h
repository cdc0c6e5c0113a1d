// Rasterised silhouettes for comparing a surface's outline with its sketch:
// pixel centres of a grid over a box, filled by a polygon or by the xy
// projection of a mesh's triangles.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <vector>

#include "SketchToSurfaceTestSupport.h"
#include "mesh/TriMesh.h"

namespace rigmesh::surfacetest {

class SilhouetteGrid {
  public:
    SilhouetteGrid(const Eigen::AlignedBox2d& box, int resolution)
        : box_(box), resolution_(resolution), filled_(resolution * resolution, false) {}

    Vec2 centre(int i, int j) const {
        const Vec2 size = box_.sizes();
        return box_.min() +
               Vec2((i + 0.5) * size.x() / resolution_, (j + 0.5) * size.y() / resolution_);
    }

    void fillPolygon(const std::vector<Vec2>& polygon) {
        for (int j = 0; j < resolution_; ++j)
            for (int i = 0; i < resolution_; ++i)
                if (testsupport::insidePolygon(polygon, centre(i, j)))
                    filled_[j * resolution_ + i] = true;
    }

    // Fills the pixels whose centres lie in the triangle's xy projection,
    // whichever way the projection is oriented.
    void fillTriangle(const Vec2& a, const Vec2& b, const Vec2& c) {
        using testsupport::cross2;
        const double area = cross2(b - a, c - a);
        if (area == 0.0)
            return;
        const auto [low, high] = pixelRange(a, b, c);
        for (int j = low.y(); j <= high.y(); ++j)
            for (int i = low.x(); i <= high.x(); ++i) {
                const Vec2 p = centre(i, j);
                const double u = cross2(b - a, p - a) / area;
                const double v = cross2(c - b, p - b) / area;
                const double w = cross2(a - c, p - c) / area;
                if (u >= 0 && v >= 0 && w >= 0)
                    filled_[j * resolution_ + i] = true;
            }
    }

    void fillProjection(const TriMesh& mesh) {
        for (const auto& f : mesh.faces)
            fillTriangle(mesh.vertices[f[0]].head<2>(), mesh.vertices[f[1]].head<2>(),
                         mesh.vertices[f[2]].head<2>());
    }

    bool filled(int i, int j) const { return filled_[j * resolution_ + i]; }
    int resolution() const { return resolution_; }

    int filledCount() const {
        return static_cast<int>(std::count(filled_.begin(), filled_.end(), true));
    }

    // Intersection over union of two grids over the same box.
    static double intersectionOverUnion(const SilhouetteGrid& a, const SilhouetteGrid& b) {
        int both = 0, either = 0;
        for (std::size_t k = 0; k < a.filled_.size(); ++k) {
            both += a.filled_[k] && b.filled_[k] ? 1 : 0;
            either += a.filled_[k] || b.filled_[k] ? 1 : 0;
        }
        return either > 0 ? static_cast<double>(both) / either : 0.0;
    }

  private:
    std::pair<Eigen::Vector2i, Eigen::Vector2i> pixelRange(const Vec2& a, const Vec2& b,
                                                           const Vec2& c) const {
        const Vec2 low = a.cwiseMin(b).cwiseMin(c);
        const Vec2 high = a.cwiseMax(b).cwiseMax(c);
        const Vec2 scale = Vec2::Constant(resolution_).cwiseQuotient(box_.sizes());
        const auto clampIndex = [&](double x) {
            return std::clamp(static_cast<int>(std::floor(x)), 0, resolution_ - 1);
        };
        const Vec2 l = (low - box_.min()).cwiseProduct(scale);
        const Vec2 h = (high - box_.min()).cwiseProduct(scale);
        return {{clampIndex(l.x()), clampIndex(l.y())}, {clampIndex(h.x()), clampIndex(h.y())}};
    }

    Eigen::AlignedBox2d box_;
    int resolution_;
    std::vector<bool> filled_;
};

}  // namespace rigmesh::surfacetest
