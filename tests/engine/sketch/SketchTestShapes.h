// Synthetic strokes for the sketch tests.
#pragma once

#include <cmath>
#include <numbers>
#include <vector>

#include "base/Types.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {

// `count` points on a circle of `radius` around `centre`, from angle `begin`
// over `turns` full turns (counter-clockwise when turns > 0). With
// `radiusGrowth` the radius changes linearly by that much along the stroke.
inline std::vector<Vec2> circleStroke(std::size_t count, double turns, double radius = 1.0,
                                      const Vec2& centre = Vec2::Zero(), double begin = 0.0,
                                      double radiusGrowth = 0.0) {
    std::vector<Vec2> points;
    for (std::size_t i = 0; i < count; ++i) {
        const double s = static_cast<double>(i) / static_cast<double>(count);
        const double angle = begin + 2.0 * std::numbers::pi * turns * s;
        const double r = radius + radiusGrowth * s;
        points.push_back(centre + r * Vec2(std::cos(angle), std::sin(angle)));
    }
    return points;
}

inline std::vector<Vec2> transformed(const std::vector<Vec2>& points, double scale,
                                     double angle = 0.0, const Vec2& offset = Vec2::Zero()) {
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    std::vector<Vec2> out;
    for (const Vec2& p : points) {
        out.push_back(scale * Vec2(c * p.x() - s * p.y(), s * p.x() + c * p.y()) + offset);
    }
    return out;
}

}  // namespace rigmesh
