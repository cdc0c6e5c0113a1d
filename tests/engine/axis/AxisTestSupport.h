// Helpers for the chordal axis and decomposition tests.
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "SketchToSurfaceTestSupport.h"
#include "axis/ChordalAxis.h"
#include "geometry/ConstrainedTriangulation.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh::axistest {

// The pruned chordal axis of a raw stroke, cleaned as the pipeline does;
// `spacing` > 0 overrides the cleaner's relative spacing.
inline ChordalAxis axisOfStroke(const std::vector<Vec2>& stroke, double spacing = 0.0) {
    StrokeCleanOptions options;
    options.spacing = spacing;
    return computeChordalAxis(triangulatePolygon(cleanStroke(stroke, options).points));
}

inline int countLive(const ChordalAxis& axis, TriangleKind kind) {
    int count = 0;
    for (std::size_t t = 0; t < axis.kind.size(); ++t)
        count += !axis.pruned[t] && axis.kind[t] == kind ? 1 : 0;
    return count;
}

// Branches with at least one terminal end: the limbs of the shape.
inline int countLimbBranches(const ChordalAxis& axis) {
    int count = 0;
    for (const AxisBranch& branch : axis.branches)
        count += axis.kind[branch.startNode] == TriangleKind::Terminal ||
                         axis.kind[branch.endNode] == TriangleKind::Terminal
                     ? 1
                     : 0;
    return count;
}

inline int nearestPolygonVertex(const ChordalAxis& axis, const Vec2& p) {
    const auto& points = axis.cdt.points;
    int best = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
        if ((points[i] - p).norm() < (points[best] - p).norm())
            best = static_cast<int>(i);
    return best;
}

inline std::vector<int> trianglesAround(const ChordalAxis& axis, int vertex) {
    std::vector<int> triangles;
    for (std::size_t t = 0; t < axis.cdt.triangles.size(); ++t) {
        const auto& tri = axis.cdt.triangles[t];
        if (std::find(tri.begin(), tri.end(), vertex) != tri.end())
            triangles.push_back(static_cast<int>(t));
    }
    return triangles;
}

// A horizontal tube (a stadium from x = 0 to 8, radius 0.5) with a shallow
// bump on its top side at x = 2 and a long limb hanging from its bottom side
// at x = 4, counter-clockwise, sampled every `step`.
struct TubeWithBumpAndLimb {
    std::vector<Vec2> outline;
    Vec2 bumpApex, limbTip, leftEnd, rightEnd;
    double tubeRadius, limbHalfWidth;
};

inline TubeWithBumpAndLimb tubeWithBumpAndLimb(double step) {
    using testsupport::appendArc;
    using testsupport::appendSegment;
    const double pi = std::numbers::pi;
    const double length = 8.0, radius = 0.5;
    const double limbHalfWidth = 0.4, limbLength = 3.0;
    // The bump: an arc of radius 0.25 whose centre is 0.1 below the top side,
    // so it rises 0.15 above the side over a base about 0.46 wide.
    const double bumpRadius = 0.25, bumpDepth = 0.1, bumpX = 2.0;
    const double bumpAngle = std::asin(bumpDepth / bumpRadius);
    const double limbX = 4.0;

    TubeWithBumpAndLimb shape;
    auto& out = shape.outline;
    appendSegment(out, {0, -radius}, {limbX - limbHalfWidth, -radius}, step);
    appendSegment(out, {limbX - limbHalfWidth, -radius},
                  {limbX - limbHalfWidth, -radius - limbLength}, step);
    appendArc(out, {limbX, -radius - limbLength}, limbHalfWidth, pi, 2 * pi, step);
    out.pop_back();
    appendSegment(out, {limbX + limbHalfWidth, -radius - limbLength},
                  {limbX + limbHalfWidth, -radius}, step);
    appendSegment(out, {limbX + limbHalfWidth, -radius}, {length, -radius}, step);
    appendArc(out, {length, 0}, radius, -pi / 2, pi / 2, step);
    out.pop_back();
    const double bumpHalfBase = bumpRadius * std::cos(bumpAngle);
    appendSegment(out, {length, radius}, {bumpX + bumpHalfBase, radius}, step);
    appendArc(out, {bumpX, radius - bumpDepth}, bumpRadius, bumpAngle, pi - bumpAngle, step);
    out.pop_back();
    appendSegment(out, {bumpX - bumpHalfBase, radius}, {0, radius}, step);
    appendArc(out, {0, 0}, radius, pi / 2, 3 * pi / 2, step);
    out.pop_back();

    shape.tubeRadius = radius;
    shape.limbHalfWidth = limbHalfWidth;
    shape.bumpApex = {bumpX, radius - bumpDepth + bumpRadius};
    shape.limbTip = {limbX, -radius - limbLength - limbHalfWidth};
    shape.leftEnd = {-radius, 0};
    shape.rightEnd = {length + radius, 0};
    return shape;
}

}  // namespace rigmesh::axistest
