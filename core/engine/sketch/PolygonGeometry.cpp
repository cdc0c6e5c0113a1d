#include "sketch/PolygonGeometry.h"

#include <algorithm>
#include <cmath>

namespace rigmesh {

namespace {

double cross(const Vec2& o, const Vec2& a, const Vec2& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

double signedArea(const Polyline2& polygon) {
    double twice = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& p = polygon[i];
        const Vec2& q = polygon[(i + 1) % polygon.size()];
        twice += p.x() * q.y() - q.x() * p.y();
    }
    return twice / 2.0;
}

double convexHullArea(Polyline2 points) {
    if (points.size() < 3) {
        return 0.0;
    }
    // Andrew's monotone chain.
    std::sort(points.begin(), points.end(), [](const Vec2& a, const Vec2& b) {
        return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
    });
    Polyline2 hull(2 * points.size());
    std::size_t k = 0;
    for (const Vec2& p : points) {
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= 0.0) {
            --k;
        }
        hull[k++] = p;
    }
    const std::size_t lower = k + 1;
    for (auto it = points.rbegin() + 1; it != points.rend(); ++it) {
        while (k >= lower && cross(hull[k - 2], hull[k - 1], *it) <= 0.0) {
            --k;
        }
        hull[k++] = *it;
    }
    hull.resize(k - 1);
    return std::abs(signedArea(hull));
}

double boundingBoxDiagonal(const Polyline2& points) {
    if (points.empty()) {
        return 0.0;
    }
    Vec2 low = points.front();
    Vec2 high = low;
    for (const Vec2& p : points) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    return (high - low).norm();
}

double polylineLength(const Polyline2& points, bool closed) {
    double length = 0.0;
    for (std::size_t i = 1; i < points.size(); ++i) {
        length += (points[i] - points[i - 1]).norm();
    }
    if (closed && points.size() > 1) {
        length += (points.front() - points.back()).norm();
    }
    return length;
}

Polyline2 resampleClosed(const Polyline2& polygon, std::size_t count) {
    const double step = polylineLength(polygon, true) / static_cast<double>(count);
    Polyline2 result;
    result.reserve(count);
    result.push_back(polygon.front());
    // Walk the edges, emitting a point each time the travelled length reaches
    // the next multiple of `step`.
    double travelled = 0.0;
    for (std::size_t i = 0; i < polygon.size() && result.size() < count; ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        const double length = (b - a).norm();
        while (result.size() < count) {
            const double target = step * static_cast<double>(result.size());
            if (target > travelled + length) {
                break;
            }
            const double t = length > 0.0 ? (target - travelled) / length : 0.0;
            result.push_back(a + t * (b - a));
        }
        travelled += length;
    }
    // Each sample lies a full step before the end of the walk, so rounding
    // cannot lose one in practice; should it, fill in on the closing edge.
    while (result.size() < count) {
        result.push_back((result.back() + polygon.front()) / 2.0);
    }
    return result;
}

Polyline2 taubinSmoothClosed(Polyline2 polygon, int iterations) {
    constexpr double lambda = 0.5;
    constexpr double mu = -0.53;
    const std::size_t n = polygon.size();
    if (n < 3) {
        return polygon;
    }
    Polyline2 next(n);
    for (int iteration = 0; iteration < iterations; ++iteration) {
        for (const double factor : {lambda, mu}) {
            for (std::size_t i = 0; i < n; ++i) {
                const Vec2 average = (polygon[(i + n - 1) % n] + polygon[(i + 1) % n]) / 2.0;
                next[i] = polygon[i] + factor * (average - polygon[i]);
            }
            std::swap(polygon, next);
        }
    }
    return polygon;
}

Vec2 closestPointOnSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    const Vec2 ab = b - a;
    const double length2 = ab.squaredNorm();
    const double t = length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0;
    return a + t * ab;
}

double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    return (closestPointOnSegment(p, a, b) - p).norm();
}

double turnAngle(const Vec2& in, const Vec2& out) {
    return std::atan2(in.x() * out.y() - in.y() * out.x(), in.dot(out));
}

bool insidePolygon(const Polyline2& polygon, const Vec2& p) {
    bool inside = false;
    for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[j];
        if ((a.y() > p.y()) != (b.y() > p.y()) &&
            p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
            inside = !inside;
    }
    return inside;
}

Vec2 pointAtArcLength(const Polyline2& polyline, double distance) {
    for (std::size_t i = 1; i < polyline.size(); ++i) {
        const double step = (polyline[i] - polyline[i - 1]).norm();
        if (distance <= step && step > 0)
            return polyline[i - 1] + distance / step * (polyline[i] - polyline[i - 1]);
        distance -= step;
    }
    return polyline.back();
}

}  // namespace rigmesh
