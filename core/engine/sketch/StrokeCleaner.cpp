#include "sketch/StrokeCleaner.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

#include "base/Error.h"
#include "sketch/PolygonGeometry.h"
#include "sketch/SegmentCrossings.h"
#include "sketch/StrokeClosing.h"
#include "sketch/StrokeCrossingError.h"

namespace rigmesh {

namespace {

// Points closer than this fraction of the stroke's size count as one.
constexpr double kDuplicateTolerance = 1e-9;
// A stroke whose (hull or final) area is below this fraction of its squared
// bounding-box diagonal encloses no area worth modelling.
constexpr double kMinRelativeArea = 1e-4;
// With at most this many distinct points left after dropping at least as many
// repeated ones, the input is repeated clicks rather than a drawn stroke.
constexpr std::size_t kFewDistinctPoints = 8;
// Bounds on the number of points of the cleaned polygon.
constexpr std::size_t kMinSamples = 12;
constexpr std::size_t kMaxSamples = 200000;
// How many times the spacing may be halved to resolve thin parts.
constexpr int kMaxRefinements = 3;

// Coordinates below `negligible` in size print as 0 instead of as rounding noise.
std::string formatPoint(const Vec2& p, double negligible = 0.0) {
    const auto shown = [negligible](double v) { return std::abs(v) <= negligible ? 0.0 : v; };
    std::ostringstream out;
    out.precision(4);
    out << "(" << shown(p.x()) << ", " << shown(p.y()) << ")";
    return out.str();
}

// Maps the stroke into [-1, 1]^2 and back, so that every tolerance below is
// relative to the stroke's size and huge or tiny coordinates stay finite.
struct Normalization {
    Vec2 centre;
    double scale;  // half the larger side of the bounding box

    Vec2 toUnit(const Vec2& p) const { return (p - centre) / scale; }
    Vec2 fromUnit(const Vec2& p) const { return p * scale + centre; }
};

Normalization normalizationOf(const std::vector<Vec2>& raw) {
    Vec2 low = raw.front();
    Vec2 high = low;
    for (const Vec2& p : raw) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    // Halving before subtracting avoids overflow near the largest doubles.
    const Vec2 half = high / 2.0 - low / 2.0;
    return {low / 2.0 + high / 2.0, half.maxCoeff()};
}

void checkFinite(const std::vector<Vec2>& raw) {
    for (std::size_t i = 0; i < raw.size(); ++i) {
        if (!raw[i].allFinite()) {
            throw Error(MessageId::StrokeNotFinite, i, formatPoint(raw[i]));
        }
    }
}

// Drops consecutive points closer than `tolerance`, and final points that
// repeat the first one (an explicitly closed stroke).
Polyline2 withoutRepeats(const Polyline2& points, double tolerance) {
    Polyline2 kept;
    for (const Vec2& p : points) {
        if (kept.empty() || (p - kept.back()).norm() > tolerance) {
            kept.push_back(p);
        }
    }
    while (kept.size() > 1 && (kept.back() - kept.front()).norm() <= tolerance) {
        kept.pop_back();
    }
    return kept;
}

void checkEnoughPoints(std::size_t rawCount, std::size_t distinct) {
    if (distinct < 3) {
        if (distinct == 1)
            throw Error(MessageId::StrokeOneDistinctPoint);
        throw Error(MessageId::StrokeTooFewDistinctPoints, distinct);
    }
    const std::size_t repeated = rawCount - distinct;
    if (distinct <= kFewDistinctPoints && repeated >= distinct) {
        throw Error(MessageId::StrokeRepeatsPositions, rawCount, distinct, repeated);
    }
}

// Keeps points at least `minStep` apart (always keeping both ends), so later
// steps cost time in proportion to the stroke's shape, not its raw density.
Polyline2 decimate(const Polyline2& points, double minStep) {
    Polyline2 kept{points.front()};
    for (std::size_t i = 1; i + 1 < points.size(); ++i) {
        if ((points[i] - kept.back()).norm() >= minStep) {
            kept.push_back(points[i]);
        }
    }
    if (kept.size() > 1 && (points.back() - kept.back()).norm() < minStep) {
        kept.pop_back();
    }
    kept.push_back(points.back());
    return kept;
}

std::optional<Vec2> firstSelfCrossing(const Polyline2& polygon) {
    const std::size_t n = polygon.size();
    std::vector<Segment2> segments;
    segments.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        segments.push_back({polygon[i], polygon[(i + 1) % n]});
    }
    const auto crossings = findSegmentCrossings(
        segments,
        [n](std::size_t a, std::size_t b) {
            // Neighbouring edges share a vertex; that is not a crossing.
            return b != a + 1 && !(a == 0 && b == n - 1);
        },
        true);
    if (crossings.empty()) {
        return std::nullopt;
    }
    return crossings.front().point;
}

void orientCounterClockwise(Polyline2& polygon) {
    if (signedArea(polygon) < 0.0) {
        std::reverse(polygon.begin() + 1, polygon.end());
    }
}

struct Sampling {
    Polyline2 polygon;             // counter-clockwise, uniformly spaced
    std::optional<Vec2> crossing;  // where it crosses itself, if it does
};

// Resamples the closed outline with `count` points, then smooths and resamples
// again to restore uniform spacing. Should smoothing make a thin part touch
// itself, the unsmoothed samples are kept.
Sampling sampleOutline(const Polyline2& outline, std::size_t count,
                       const StrokeCleanOptions& options) {
    Polyline2 polygon = resampleClosed(outline, count);
    orientCounterClockwise(polygon);
    if (options.smoothingIterations > 0) {
        Polyline2 smoothed =
            resampleClosed(taubinSmoothClosed(polygon, options.smoothingIterations), count);
        if (!firstSelfCrossing(smoothed)) {
            return {std::move(smoothed), std::nullopt};
        }
    }
    const auto crossing = firstSelfCrossing(polygon);
    return {std::move(polygon), crossing};
}

// Anti-aliasing before resampling: mouse jitter finer than the sample spacing
// would otherwise alias into zig-zags (and false self-crossings) once
// resampled. Resample at a quarter of the spacing and average each point with
// its two neighbours on either side, twice: a low-pass over about one spacing.
Polyline2 lowPassClosed(const Polyline2& outline, double spacing) {
    const double length = polylineLength(outline, true);
    const auto count = static_cast<std::size_t>(std::ceil(length / (spacing / 4.0)));
    if (count < 16 || count > kMaxSamples)
        return outline;
    Polyline2 fine = resampleClosed(outline, count);
    const long n = static_cast<long>(fine.size());
    for (int pass = 0; pass < 2; ++pass) {
        Polyline2 averaged(fine.size(), Vec2::Zero());
        for (long i = 0; i < n; ++i) {
            for (long k = -2; k <= 2; ++k)
                averaged[i] += fine[((i + k) % n + n) % n];
            averaged[i] /= 5.0;
        }
        fine = std::move(averaged);
    }
    return fine;
}

double unitSpacing(const StrokeCleanOptions& options, const Normalization& unit,
                   double unitDiagonal) {
    if (options.spacing > 0.0 && std::isfinite(options.spacing)) {
        return options.spacing / unit.scale;
    }
    if (!(options.relativeSpacing > 0.0) || !std::isfinite(options.relativeSpacing)) {
        throw std::logic_error(
            "The stroke spacing must be positive: set a relative spacing above 0 or an "
            "absolute spacing.");
    }
    return options.relativeSpacing * unitDiagonal;
}

std::size_t sampleCount(double length, double spacing) {
    const double count = std::round(length / spacing);
    if (!(count <= static_cast<double>(kMaxSamples))) {
        throw Error(MessageId::StrokeTooLong, kMaxSamples);
    }
    return std::max(kMinSamples, static_cast<std::size_t>(count));
}

}  // namespace

CleanPolygon cleanStroke(const std::vector<Vec2>& raw, const StrokeCleanOptions& options) {
    if (options.smoothingIterations < 0) {
        throw std::logic_error("The number of smoothing iterations cannot be negative.");
    }
    checkFinite(raw);
    if (raw.empty()) {
        checkEnoughPoints(0, 0);
    }
    const Normalization unit = normalizationOf(raw);
    if (!(unit.scale > 0.0)) {
        checkEnoughPoints(raw.size(), 1);
    }
    Polyline2 stroke;
    stroke.reserve(raw.size());
    for (const Vec2& p : raw) {
        stroke.push_back(unit.toUnit(p));
    }
    const double diagonal = boundingBoxDiagonal(stroke);
    stroke = withoutRepeats(stroke, kDuplicateTolerance * diagonal);
    checkEnoughPoints(raw.size(), stroke.size());
    if (convexHullArea(stroke) < kMinRelativeArea * diagonal * diagonal) {
        throw Error(MessageId::StrokeOnALine);
    }

    // Bound the work before anything costlier than linear time.
    const double rawSpacing = unitSpacing(options, unit, diagonal);
    sampleCount(polylineLength(stroke, true), rawSpacing);
    // Decimate no coarser than the default spacing, whatever was asked for,
    // so that a coarse spacing cannot erase the shape before it is closed.
    const double decimationStep = std::min(rawSpacing, diagonal / 60.0) / 4.0;
    stroke = withoutRepeats(closeStroke(decimate(stroke, decimationStep)),
                            kDuplicateTolerance * diagonal);
    if (stroke.size() < 3) {
        checkEnoughPoints(raw.size(), stroke.size());
    }

    // Uniform arc-length samples, relative to the closed outline's own size.
    // Parts of the outline thinner than the spacing can touch once sampled;
    // finer spacings resolve them. An outline that still crosses itself at
    // the finest spacing really does.
    const double closedDiagonal = boundingBoxDiagonal(stroke);
    const double spacing = unitSpacing(options, unit, closedDiagonal);
    if (options.smoothingIterations > 0)
        stroke = lowPassClosed(stroke, spacing);
    const double length = polylineLength(stroke, true);
    Sampling sampling = sampleOutline(stroke, sampleCount(length, spacing), options);
    for (int refinement = 1; sampling.crossing && refinement <= kMaxRefinements; ++refinement) {
        const double finer = spacing / std::pow(2.0, refinement);
        if (length / finer > static_cast<double>(kMaxSamples)) {
            break;
        }
        sampling = sampleOutline(stroke, sampleCount(length, finer), options);
    }
    if (sampling.crossing) {
        const Vec2 crossing = unit.fromUnit(*sampling.crossing);
        throw StrokeCrossingError(crossing, formatPoint(crossing, 1e-9 * unit.scale));
    }
    const Polyline2& polygon = sampling.polygon;
    if (std::abs(signedArea(polygon)) < kMinRelativeArea * closedDiagonal * closedDiagonal) {
        throw Error(MessageId::StrokeNoWidth);
    }

    CleanPolygon result;
    result.points.reserve(polygon.size());
    for (const Vec2& p : polygon) {
        result.points.push_back(unit.fromUnit(p));
        if (!result.points.back().allFinite()) {
            throw Error(MessageId::StrokeTooLarge);
        }
    }
    result.spacing =
        polylineLength(polygon, true) / static_cast<double>(polygon.size()) * unit.scale;
    return result;
}

}  // namespace rigmesh
