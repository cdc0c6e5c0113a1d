// Shared helpers for the sketch-to-surface tests (test_axis, test_surface):
// the shared sketch files, synthetic outlines and plain polygon geometry,
// written without the engine's own helpers.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "base/Types.h"
#include "sketch/PolygonGeometry.h"
#include "sketch/Sketch.h"

namespace rigmesh::testsupport {

inline std::string sharedSketchPath(const std::string& name) {
    return std::string(RIGMESH_SHARED_SKETCHES) + "/" + name + ".json";
}

inline std::vector<Vec2> sharedSketchPoints(const std::string& name) {
    return readSketchFile(sharedSketchPath(name)).points;
}

// Stems of the shared .json sketches, sorted; `bad` selects the bad_* ones.
inline std::vector<std::string> sharedSketchNames(bool bad) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(RIGMESH_SHARED_SKETCHES)) {
        const std::string stem = entry.path().stem().string();
        if (entry.path().extension() == ".json" && (stem.rfind("bad_", 0) == 0) == bad)
            names.push_back(stem);
    }
    std::sort(names.begin(), names.end());
    return names;
}

// Names parameterised tests after the sketch.
inline std::string sketchTestName(const ::testing::TestParamInfo<std::string>& param) {
    return param.param;
}

inline double cross2(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// The engine's shoelace area and even-odd test (sketch/PolygonGeometry.h).
using rigmesh::insidePolygon;
using rigmesh::signedArea;

// Counter-clockwise polar outline r(theta) with `count` samples.
template <typename Radius>
std::vector<Vec2> polarOutline(int count, Radius radius, const Vec2& centre = Vec2::Zero()) {
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        const double theta = 2.0 * std::numbers::pi * i / count;
        points.push_back(centre + radius(theta) * Vec2(std::cos(theta), std::sin(theta)));
    }
    return points;
}

// An ellipse with a round bump on its top: the bump is pruned as
// an insignificant branch off the middle of the body, so it once came out
// missing, with a dimple and a pointed tip on the side opposite.
inline std::vector<Vec2> blobWithBump() {
    std::vector<Vec2> points;
    constexpr int kCount = 240;
    for (int i = 0; i < kCount; ++i) {
        const double t = 2 * std::numbers::pi * i / kCount;
        const double bump = 0.45 * std::exp(-std::pow((t - std::numbers::pi / 2) / 0.3, 2));
        points.emplace_back((1.6 + bump) * std::cos(t), (1.0 + bump) * std::sin(t));
    }
    return points;
}

// A body with seven bumps alternating on its top and bottom (a caterpillar):
// runs of neighbouring body sleeves each carry a pruned bump.
inline std::vector<Vec2> bumpyCaterpillar() {
    std::vector<Vec2> points;
    constexpr int kCount = 480;
    for (int i = 0; i < kCount; ++i) {
        const double t = 2 * std::numbers::pi * i / kCount;
        const double x = 3.0 * std::cos(t);
        const double side = std::sin(t) >= 0 ? 1.0 : -1.0;
        double bump = 0.0;
        for (int k = -3; k <= 3; ++k)
            if ((k % 2 == 0) == (side > 0))
                bump += 0.3 * std::exp(-std::pow((x - 0.8 * k) / 0.18, 2));
        points.emplace_back(x, (0.7 + bump) * std::sin(t));
    }
    return points;
}

// A star with `arms` rounded arms of length about `armLength` around a body
// of radius `body`; the higher `sharpness`, the thinner the arms.
inline std::vector<Vec2> armedStar(int arms, double body, double armLength, int sharpness = 6,
                                   int count = 600) {
    return polarOutline(count, [=](double theta) {
        const double lobe = std::abs(std::cos(0.5 * arms * theta));
        return body + armLength * std::pow(lobe, sharpness);
    });
}

// Appends the arc of `centre`, `radius` from angle `from` to `to` (radians,
// either direction) in steps of about `step`, end points included.
inline void appendArc(std::vector<Vec2>& out, const Vec2& centre, double radius, double from,
                      double to, double step) {
    const int count = std::max(2, static_cast<int>(std::ceil(std::abs(to - from) * radius / step)));
    for (int i = 0; i <= count; ++i) {
        const double angle = from + (to - from) * i / count;
        out.push_back(centre + radius * Vec2(std::cos(angle), std::sin(angle)));
    }
}

// Appends the segment from a to b (a included, b excluded) in steps of about `step`.
inline void appendSegment(std::vector<Vec2>& out, const Vec2& a, const Vec2& b, double step) {
    const int count = std::max(1, static_cast<int>(std::ceil((b - a).norm() / step)));
    for (int i = 0; i < count; ++i)
        out.push_back(a + (b - a) * (static_cast<double>(i) / count));
}

// A counter-clockwise stadium: the segment (0,0)-(length,0) thickened by `radius`.
inline std::vector<Vec2> stadium(double length, double radius, double step) {
    const double pi = std::numbers::pi;
    std::vector<Vec2> out;
    appendSegment(out, {0, -radius}, {length, -radius}, step);
    appendArc(out, {length, 0}, radius, -pi / 2, pi / 2, step);
    out.pop_back();
    appendSegment(out, {length, radius}, {0, radius}, step);
    appendArc(out, {0, 0}, radius, pi / 2, 3 * pi / 2, step);
    out.pop_back();
    return out;
}

// A random star-shaped polygon around the origin: `count` angles with random
// radii; with `neck`, two opposite lobes are pinched to a narrow waist.
inline std::vector<Vec2> randomStarPolygon(std::mt19937& random, int count, double noise,
                                           bool neck) {
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const double phase = 2.0 * std::numbers::pi * unit(random);
    const double waist = 0.05 + 0.2 * unit(random);
    const double lobes = 1.0 + std::floor(4.0 * unit(random));
    std::vector<Vec2> points;
    for (int i = 0; i < count; ++i) {
        const double theta = 2.0 * std::numbers::pi * i / count;
        double r = 1.0 + 0.4 * std::sin(lobes * theta + phase);
        if (neck)
            r *= waist + (1.0 - waist) * std::pow(std::cos(theta + phase), 2);
        r *= 1.0 + noise * (2.0 * unit(random) - 1.0);
        points.push_back(r * Vec2(std::cos(theta), std::sin(theta)));
    }
    return points;
}

}  // namespace rigmesh::testsupport
