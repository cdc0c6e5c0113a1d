#include "cut/CutSurface.h"

#include <algorithm>
#include <limits>

#include "base/Error.h"

namespace rigmesh {

CutSurface CutSurface::plane(const Vec3& point, const Vec3& normal) {
    CutSurface s;
    s.point_ = point;
    s.normal_ = normal.normalized();
    s.u_ = s.normal_.unitOrthogonal();
    s.v_ = s.normal_.cross(s.u_);
    return s;
}

CutSurface CutSurface::swept(std::vector<Vec3> stroke, const Vec3& direction) {
    if (stroke.size() < 2 || !(direction.norm() > 0.0))
        throw Error(MessageId::CutStrokeTooShort);
    const Vec3 d = direction.normalized();
    // Onto the plane through the first point normal to the sweep.
    for (Vec3& p : stroke)
        p -= d * d.dot(p - stroke.front());
    stroke.erase(std::unique(stroke.begin(), stroke.end()), stroke.end());
    const Vec3 chord = stroke.back() - stroke.front();
    if (stroke.size() < 2 || !(chord.norm() > 0.0))
        throw Error(MessageId::CutStrokeClosed);

    double deviation = 0.0;
    const Vec3 along = chord.normalized();
    for (const Vec3& p : stroke) {
        const Vec3 off = p - stroke.front();
        deviation = std::max(deviation, (off - along * along.dot(off)).norm());
    }
    // A straight stroke sweeps one strip between its ends.
    if (deviation <= 0.01 * chord.norm())
        stroke = {stroke.front(), stroke.back()};
    CutSurface s;
    s.direction_ = d;
    s.stroke_ = std::move(stroke);
    s.arc_.assign(s.stroke_.size(), 0.0);
    for (std::size_t i = 1; i < s.stroke_.size(); ++i)
        s.arc_[i] = s.arc_[i - 1] + (s.stroke_[i] - s.stroke_[i - 1]).norm();
    s.point_ = s.stroke_.front();
    return s;
}

CutSurface::Nearest CutSurface::nearest(const Vec3& p) const {
    const Vec3 q = p - direction_ * direction_.dot(p - stroke_.front());
    Nearest best{stroke_.front(), 0.0, 0};
    double bestDistance = std::numeric_limits<double>::infinity();
    for (int i = 0; i + 1 < static_cast<int>(stroke_.size()); ++i) {
        const Vec3 a = stroke_[i], e = stroke_[i + 1] - a;
        const double t = std::clamp((q - a).dot(e) / e.squaredNorm(), 0.0, 1.0);
        const Vec3 c = a + t * e;
        const double d = (q - c).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = {c, arc_[i] + t * (arc_[i + 1] - arc_[i]), i};
        }
    }
    return best;
}

double CutSurface::side(const Vec3& p) const {
    if (isPlane())
        return normal_.dot(p - point_);
    const Nearest n = nearest(p);
    const Vec3 e = (stroke_[n.segment + 1] - stroke_[n.segment]).normalized();
    const Vec3 q = p - direction_ * direction_.dot(p - stroke_.front());
    return (q - n.point).dot(e.cross(direction_));
}

Vec3 CutSurface::crossing(const Vec3& a, const Vec3& b) const {
    double sa = side(a), sb = side(b);
    if (isPlane())
        return a + sa / (sa - sb) * (b - a);
    // Bisection: the side is continuous along the segment.
    Vec3 lo = a, hi = b;
    for (int i = 0; i < 40; ++i) {  // 2^-40 of the segment: far below any edge
        const Vec3 mid = 0.5 * (lo + hi);
        const double sm = side(mid);
        if ((sm < 0.0) == (sa < 0.0)) {
            lo = mid;
            sa = sm;
        } else {
            hi = mid;
            sb = sm;
        }
    }
    return 0.5 * (lo + hi);
}

Vec2 CutSurface::toPatch(const Vec3& p) const {
    if (isPlane())
        return {u_.dot(p - point_), v_.dot(p - point_)};
    return {nearest(p).arc, direction_.dot(p - stroke_.front())};
}

Vec3 CutSurface::fromPatch(const Vec2& q) const {
    if (isPlane())
        return point_ + q.x() * u_ + q.y() * v_;
    const double s = std::clamp(q.x(), 0.0, arc_.back());
    const auto at = std::upper_bound(arc_.begin(), arc_.end(), s);
    const int i = std::clamp(static_cast<int>(at - arc_.begin()) - 1, 0,
                             static_cast<int>(stroke_.size()) - 2);
    const double span = arc_[i + 1] - arc_[i];
    const double t = span > 0.0 ? (s - arc_[i]) / span : 0.0;
    return stroke_[i] + t * (stroke_[i + 1] - stroke_[i]) + q.y() * direction_;
}

TriMesh CutSurface::strip(const Eigen::AlignedBox3d& box) const {
    const double reach = 2.0 * box.diagonal().norm() + 1.0;
    const std::vector<Vec3>& path = stroke_;
    const double centre = direction_.dot(box.center() - stroke_.front());
    TriMesh mesh;
    for (const Vec3& p : path) {
        mesh.vertices.push_back(p + (centre - reach) * direction_);
        mesh.vertices.push_back(p + (centre + reach) * direction_);
    }
    for (int i = 0; i + 1 < static_cast<int>(path.size()); ++i) {
        const int a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
        mesh.faces.push_back({a, c, d});
        mesh.faces.push_back({a, d, b});
    }
    return mesh;
}

}  // namespace rigmesh
