// The per-triangle and per-weight terms of bone heat (paper 2.4) that the
// global solver (BoneHeatSolver) and the local re-computation after a merge
// (LocalBoneHeat, paper 3.2.2) share, so both solve the same equation.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <Eigen/Geometry>  // cross(): declared in Core, defined here

#include "base/Types.h"
#include "rig/BoneHeatSolver.h"

namespace rigmesh {

// A triangle with an angle whose sine is below this (relative, so
// scale-free), a repeated corner or a zero-length edge has no usable angles:
// its cotangents would reach 1e8 and pin a vertex. Such faces are
// left out of the Laplacian and the areas, so every cotangent stays below 1e8.
inline constexpr double kMinSineRelative = 1e-8;

// d^2 is bounded below by this fraction of the vertex area, so that a vertex
// lying on its bone gets a very large but finite heat (scale-free too).
inline constexpr double kMinDistanceSquaredPerArea = 1e-12;

// Twice the area of a triangle with usable angles, 0 for a degenerate one.
// Every corner's |e1 x e2| is this same number, so the smallest sine is
// twice the area over the product of the two longest edges.
inline double usableDoubleArea(const std::array<int, 3>& face, const std::vector<Vec3>& positions) {
    if (face[0] == face[1] || face[1] == face[2] || face[0] == face[2]) {
        return 0.0;
    }
    const Vec3& a = positions[face[0]];
    const Vec3& b = positions[face[1]];
    const Vec3& c = positions[face[2]];
    std::array<double, 3> lengths{(b - a).norm(), (c - b).norm(), (a - c).norm()};
    std::sort(lengths.begin(), lengths.end());
    const double doubleArea = (b - a).cross(c - a).norm();
    return doubleArea > 0.0 && doubleArea >= kMinSineRelative * lengths[1] * lengths[2] ? doubleArea
                                                                                        : 0.0;
}

// Blender's taper of small weights (BoneHeatOptions::taperEnd/taperStart).
inline double taperedWeight(double w, const BoneHeatOptions& options) {
    if (!(w >= options.taperEnd) || !(w > 0.0)) {
        return 0.0;
    }
    if (w >= options.taperStart) {
        return w;
    }
    return options.taperStart * (w - options.taperEnd) / (options.taperStart - options.taperEnd);
}

// A_i H_i = c A_i / d^2 for a vertex of one-ring area A_i whose closest
// visible bone is at distance d (both scale as s^0 under scaling by s).
inline double heatTerm(double area, double distance, const BoneHeatOptions& options) {
    return options.heatConstant * area /
           std::max(distance * distance, kMinDistanceSquaredPerArea * area);
}

}  // namespace rigmesh
