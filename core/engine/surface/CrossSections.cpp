#include "surface/CrossSections.h"

#include <algorithm>
#include <cmath>

#include "geometry/CatmullRom.h"
#include "geometry/CurvatureLimit.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

double cross2(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

// A chord as centre, unit direction (left to right) and half-length: the
// quantities the paper smooths.
struct ChordFrame {
    Vec2 centre;
    Vec2 direction;
    double radius;
};

ChordFrame frameOf(const Vec2& left, const Vec2& right) {
    Vec2 span = right - left;
    double length = span.norm();
    return {0.5 * (left + right), length > 0 ? Vec2(span / length) : Vec2(1, 0), 0.5 * length};
}

// Laplacian smoothing of the axis points, chord directions and radii (paper
// 2.1); the two end chords stay where they are, since they are shared with a
// connecting region or a cap.
void smoothFrames(std::vector<ChordFrame>& frames, const CrossSectionOptions& options) {
    const int count = static_cast<int>(frames.size());
    if (count < 3)
        return;
    for (int iteration = 0; iteration < options.axisSmoothingIterations; ++iteration) {
        std::vector<ChordFrame> next = frames;
        for (int i = 1; i + 1 < count; ++i) {
            const double s = options.smoothingStep;
            next[i].centre = (1 - s) * frames[i].centre +
                             s * 0.5 * (frames[i - 1].centre + frames[i + 1].centre);
            Vec2 direction = (1 - s) * frames[i].direction +
                             s * 0.5 * (frames[i - 1].direction + frames[i + 1].direction);
            if (direction.norm() > 1e-12)
                next[i].direction = direction.normalized();
            next[i].radius = (1 - s) * frames[i].radius +
                             s * 0.5 * (frames[i - 1].radius + frames[i + 1].radius);
        }
        frames = std::move(next);
    }
}

CrossSection sectionOf(const ChordFrame& frame) {
    CrossSection section;
    section.left = frame.centre - frame.radius * frame.direction;
    section.right = frame.centre + frame.radius * frame.direction;
    return section;
}

// The local edge length at a chord of this radius (resolution
// follows thickness).
double localSpacing(double radius, double spacing, const CrossSectionOptions& options) {
    return std::clamp(options.radiusFraction * radius, options.minimumSpacingFraction * spacing,
                      spacing);
}

// Resamples the smoothed body so that adjacent sections are about one local
// edge length apart on their widest side (paper 2.2), dropping any section
// that would cross its predecessor. The parameter counts local edge lengths, so sections crowd
// where the body is thin and keep the target spacing where it is wide.
std::vector<CrossSection> resampleBody(const std::vector<ChordFrame>& frames, CrossSection first,
                                       CrossSection last, double spacing,
                                       const CrossSectionOptions& options) {
    const int count = static_cast<int>(frames.size());
    auto local = [&](double radius) { return localSpacing(radius, spacing, options); };
    first.spacing = local(first.radius());
    last.spacing = local(last.radius());
    first.chordParameter = 0.0;
    last.chordParameter = count - 1;
    std::vector<double> parameter(count, 0.0);
    for (int i = 1; i < count; ++i) {
        CrossSection a = sectionOf(frames[i - 1]), b = sectionOf(frames[i]);
        double step = std::max({(a.left - b.left).norm(), (a.right - b.right).norm(),
                                (frames[i - 1].centre - frames[i].centre).norm()});
        parameter[i] =
            parameter[i - 1] + step / local(0.5 * (frames[i - 1].radius + frames[i].radius));
    }
    std::vector<CrossSection> candidates{first};
    if (count > 1) {
        const int intervals = std::max(1, static_cast<int>(std::lround(parameter.back())));
        int segment = 0;
        for (int k = 1; k < intervals; ++k) {
            double target = parameter.back() * k / intervals;
            while (segment + 2 < count && parameter[segment + 1] < target)
                ++segment;
            double span = parameter[segment + 1] - parameter[segment];
            double f = span > 0 ? std::clamp((target - parameter[segment]) / span, 0.0, 1.0) : 0.0;
            const ChordFrame& a = frames[segment];
            const ChordFrame& b = frames[segment + 1];
            ChordFrame blended{(1 - f) * a.centre + f * b.centre,
                               ((1 - f) * a.direction + f * b.direction).normalized(),
                               (1 - f) * a.radius + f * b.radius};
            candidates.push_back(sectionOf(blended));
            candidates.back().spacing = local(blended.radius);
            candidates.back().chordParameter = segment + f;
        }
        candidates.push_back(last);
    }
    // Cross sections must not intersect: keep a section only if it clashes
    // with neither the previous kept one nor the final one (sectionsClash:
    // crossing, or crowding on one side around an outline corner, where one
    // side barely moves while the other sweeps).
    std::vector<CrossSection> kept{candidates.front()};
    for (std::size_t i = 1; i + 1 < candidates.size(); ++i) {
        const CrossSection& c = candidates[i];
        if (sectionsClash(c, kept.back()) || sectionsClash(c, last))
            continue;
        kept.push_back(c);
    }
    if (candidates.size() > 1)
        kept.push_back(last);
    return kept;
}

// The smallest radius of curvature of a cap's outline path, in local edge
// lengths.
constexpr double kMinTipRadius = 1.5;

// The outline around a tip as a smooth curve: a centripetal Catmull-Rom
// spline through the path's polygon points (the polygon's neighbours beyond
// either end give the end tangents), sampled at a quarter of `spacing`. At
// a thin part the polygon is coarse against the local edge length (a foot
// 0.25 wide ends in three outline points 0.1 apart), and slicing the polygon
// itself gave a faceted tip with creases at its corners. The
// curve passes through every polygon point but those of a corner sharper
// than kMinTipRadius, which it rounds; `indices` keeps the polygon index of
// each point still on its polygon point (-1 elsewhere).
struct CapPath {
    std::vector<Vec2> points;
    std::vector<int> indices;
};

CapPath smoothCapPath(const std::vector<Vec2>& polygon, const std::vector<int>& path,
                      double spacing) {
    const int size = static_cast<int>(polygon.size());
    std::vector<Vec2> control;
    control.push_back(polygon[(path.front() - 1 + size) % size]);
    for (int i : path)
        control.push_back(polygon[i]);
    control.push_back(polygon[(path.back() + 1) % size]);
    CapPath result;
    for (std::size_t k = 1; k + 2 < control.size(); ++k) {
        const Vec2 &p0 = control[k - 1], &p1 = control[k], &p2 = control[k + 1],
                   &p3 = control[k + 2];
        result.points.push_back(p1);
        result.indices.push_back(path[k - 1]);
        const int pieces =
            std::max(1, static_cast<int>(std::ceil((p2 - p1).norm() / (0.25 * spacing))));
        for (int j = 1; j < pieces; ++j) {
            result.points.push_back(centripetalCatmullRom(p0, p1, p2, p3, double(j) / pieces));
            result.indices.push_back(-1);
        }
    }
    result.points.push_back(polygon[path.back()]);
    result.indices.push_back(path.back());
    // A corner of the outline stays a corner of the spline: on the
    // silhouette a turn of 50 degrees between two points, where an
    // obliquely ended limb was cleaned at the outline's coarse spacing.
    // Rounded to kMinTipRadius, the tip is a dome again.
    const std::vector<Vec2> onSpline = result.points;
    CurvatureFlow flow;
    flow.neighbourhood = 2;  // the turn spreads instead of moving to the next point
    limitCurvature(result.points, kMinTipRadius * spacing, flow);
    for (std::size_t i = 0; i < result.points.size(); ++i)
        if (result.points[i] != onSpline[i])
            result.indices[i] = -1;
    return result;
}

struct CapSlices {
    std::vector<CrossSection> slices;  // outward from the base
    Vec2 tip;
    int tipIndex;
};

// Continues the cross sections into a cap (paper 2.2). The outline around the
// tip (smoothCapPath) is split at the tip and each side is walked in equal
// steps: slice k joins the k-th points of both sides, like the latitude
// circles of a dome, so blunt and pointed ends both get rings about one edge
// length apart. `pathIndices` run counter-clockwise (polygon indices) from
// the base chord's right end point around the tip to its left end point.
CapSlices sliceCap(const CrossSection& base, const std::vector<Vec2>& polygon,
                   const std::vector<int>& pathIndices, double spacing) {
    const CapPath smooth = smoothCapPath(polygon, pathIndices, spacing);
    const std::vector<Vec2>& path = smooth.points;
    std::vector<double> arc(path.size(), 0.0);
    for (std::size_t i = 1; i < path.size(); ++i)
        arc[i] = arc[i - 1] + (path[i] - path[i - 1]).norm();
    // The tip is where the cap reaches farthest from its base chord (within
    // 2% of the cap's height), and there nearest the arc-length middle:
    // the middle of a round or flat end, the apex of a pointed or oblique one
    // (at the middle, an oblique thin tip folded where its apex became a
    // point on one side).
    const Vec2 baseDirection = (base.right - base.left).normalized();
    auto height = [&](const Vec2& p) { return std::abs(cross2(baseDirection, p - base.left)); };
    double highest = 0.0;
    for (const Vec2& p : path)
        highest = std::max(highest, height(p));
    std::size_t tip = 0;
    bool found = false;
    for (std::size_t i = 1; i + 1 < path.size(); ++i) {
        if (height(path[i]) < 0.98 * highest)
            continue;
        if (!found || std::abs(arc[i] - 0.5 * arc.back()) < std::abs(arc[tip] - 0.5 * arc.back()))
            tip = i;
        found = true;
    }
    CapSlices cap{{}, path[tip], smooth.indices[tip]};
    std::vector<Vec2> rightSide(path.begin(), path.begin() + static_cast<long>(tip) + 1);
    std::vector<Vec2> leftSide(path.rbegin(), path.rend() - static_cast<long>(tip));
    const double rightLength = polylineLength(rightSide, false);
    const double leftLength = polylineLength(leftSide, false);
    const int intervals =
        std::max(1, static_cast<int>(std::ceil(std::max(rightLength, leftLength) / spacing)));
    for (int k = 1; k < intervals; ++k) {
        CrossSection slice;
        slice.left = pointAtArcLength(leftSide, leftLength * k / intervals);
        slice.right = pointAtArcLength(rightSide, rightLength * k / intervals);
        slice.inCap = true;
        slice.spacing = spacing;
        const CrossSection& previous = cap.slices.empty() ? base : cap.slices.back();
        if (segmentsIntersect(slice.left, slice.right, previous.left, previous.right))
            continue;
        cap.slices.push_back(slice);
    }
    return cap;
}

// A cap's edge-length floor as a share of the body's.
constexpr double kCapFloorShare = 0.5;

CrossSection flipped(const CrossSection& s) {
    CrossSection f = s;
    std::swap(f.left, f.right);
    std::swap(f.leftPolygonIndex, f.rightPolygonIndex);
    return f;
}

}  // namespace

bool segmentsIntersect(const Vec2& a, const Vec2& b, const Vec2& c, const Vec2& d) {
    double d1 = cross2(b - a, c - a), d2 = cross2(b - a, d - a);
    double d3 = cross2(d - c, a - c), d4 = cross2(d - c, b - c);
    return ((d1 > 0) != (d2 > 0) || d1 == 0 || d2 == 0) &&
           ((d3 > 0) != (d4 > 0) || d3 == 0 || d4 == 0) &&
           std::max(std::min(a.x(), b.x()), std::min(c.x(), d.x())) <=
               std::min(std::max(a.x(), b.x()), std::max(c.x(), d.x())) &&
           std::max(std::min(a.y(), b.y()), std::min(c.y(), d.y())) <=
               std::min(std::max(a.y(), b.y()), std::max(c.y(), d.y()));
}

bool sectionsClash(const CrossSection& a, const CrossSection& b) {
    constexpr double kMinimumSideStep = 0.3;  // of the smaller spacing
    const double step = kMinimumSideStep * std::min(a.spacing, b.spacing);
    return segmentsIntersect(a.left, a.right, b.left, b.right) || (a.left - b.left).norm() < step ||
           (a.right - b.right).norm() < step;
}

CylinderSections buildCrossSections(const Decomposition& decomposition, int cylinderIndex,
                                    double spacing, const CrossSectionOptions& options) {
    const CylinderRegion& cylinder = decomposition.cylinders[cylinderIndex];
    const auto& points = decomposition.axis.cdt.points;

    std::vector<ChordFrame> frames;
    for (const auto& chord : cylinder.chords)
        frames.push_back(frameOf(points[chord[0]], points[chord[1]]));
    smoothFrames(frames, options);

    auto polygonSection = [&](const PolygonEdge& chord) {
        CrossSection s;
        s.left = points[chord[0]];
        s.right = points[chord[1]];
        s.leftPolygonIndex = chord[0];
        s.rightPolygonIndex = chord[1];
        return s;
    };
    std::vector<CrossSection> body =
        resampleBody(frames, polygonSection(cylinder.chords.front()),
                     polygonSection(cylinder.chords.back()), spacing, options);

    // A cap is sliced at its base's local edge length, down to half the
    // body's floor: a needle's tip a little wider than the floor was a dome
    // of two slices, creased against the tapering body. A cap's
    // vertex count stays bounded by its size.
    auto capSpacing = [&](const CrossSection& base) {
        return std::clamp(options.radiusFraction * base.radius(),
                          kCapFloorShare * options.minimumSpacingFraction * spacing, spacing);
    };
    CylinderSections result;
    for (const ChordFrame& frame : frames)
        result.axisChords.push_back(sectionOf(frame));
    // The end chords are the outline's own (smoothing keeps them in place).
    result.axisChords.front() = body.front();
    result.axisChords.back() = body.back();
    if (!cylinder.startCap.empty()) {
        // Seen from the start tip the cylinder runs backwards: flip, slice, flip back.
        CapSlices cap =
            sliceCap(flipped(body.front()), points, cylinder.startCap, capSpacing(body.front()));
        for (auto it = cap.slices.rbegin(); it != cap.slices.rend(); ++it)
            result.sections.push_back(flipped(*it));
        result.startTip = cap.tip;
        result.startTipPolygonIndex = cap.tipIndex;
    }
    result.sections.insert(result.sections.end(), body.begin(), body.end());
    if (!cylinder.endCap.empty()) {
        CapSlices cap = sliceCap(body.back(), points, cylinder.endCap, capSpacing(body.back()));
        result.sections.insert(result.sections.end(), cap.slices.begin(), cap.slices.end());
        result.endTip = cap.tip;
        result.endTipPolygonIndex = cap.tipIndex;
    }

    // Arc length along the axis through the section centres.
    double position = 0.0;
    Vec2 previous = result.startTip ? *result.startTip : result.sections.front().centre();
    for (const auto& section : result.sections) {
        position += (section.centre() - previous).norm();
        result.axisPosition.push_back(position);
        previous = section.centre();
    }
    result.endTipPosition = position + (result.endTip ? (*result.endTip - previous).norm() : 0.0);
    return result;
}

}  // namespace rigmesh
