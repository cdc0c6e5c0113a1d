// Outlines of unions of simple shapes, as a person draws a creature: bodies
// (ellipses) and limbs (tubes along a polyline whose radius varies along
// it), joined without blending, so a limb meets a body at a corner as a
// drawn one does. The union's boundary is traced by marching squares on a
// grid of its approximate signed distance; its largest loop is the outline.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

#include <Eigen/Geometry>

#include "base/Types.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh::testsupport {

struct EllipseShape {
    Vec2 centre = Vec2::Zero();
    double a = 1.0, b = 1.0;  // semi-axes along the rotated x and y
    double angle = 0.0;       // radians

    // Approximate signed distance: negative inside, exact zero set.
    double distance(const Vec2& p) const {
        const Vec2 d = p - centre;
        const double c = std::cos(angle), s = std::sin(angle);
        const Vec2 q(c * d.x() + s * d.y(), -s * d.x() + c * d.y());
        const double k = std::hypot(q.x() / a, q.y() / b);
        const double gradient = std::hypot(q.x() / (a * a), q.y() / (b * b));
        if (!(k > 1e-12) || !(gradient > 1e-12))
            return -std::min(a, b);
        return (k - 1.0) * k / gradient;
    }
};

// A tube along `path` whose radius runs linearly between the values given
// at its points (a limb, a finger, a tapering tentacle).
struct TubeShape {
    std::vector<Vec2> path;
    std::vector<double> radius;  // one per path point

    double distance(const Vec2& p) const {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i + 1 < path.size(); ++i) {
            const Vec2 ab = path[i + 1] - path[i];
            const double length2 = ab.squaredNorm();
            const double t =
                length2 > 0 ? std::clamp((p - path[i]).dot(ab) / length2, 0.0, 1.0) : 0.0;
            const double r = (1.0 - t) * radius[i] + t * radius[i + 1];
            best = std::min(best, (p - (path[i] + t * ab)).norm() - r);
        }
        return best;
    }

    Eigen::AlignedBox2d box() const {
        Eigen::AlignedBox2d b;
        for (std::size_t i = 0; i < path.size(); ++i) {
            b.extend(path[i] - Vec2::Constant(radius[i]));
            b.extend(path[i] + Vec2::Constant(radius[i]));
        }
        return b;
    }
};

struct ShapeUnion {
    std::vector<EllipseShape> bodies;
    std::vector<TubeShape> limbs;

    double distance(const Vec2& p) const {
        double d = std::numeric_limits<double>::infinity();
        for (const auto& body : bodies)
            d = std::min(d, body.distance(p));
        for (const auto& limb : limbs)
            d = std::min(d, limb.distance(p));
        return d;
    }

    Eigen::AlignedBox2d box() const {
        Eigen::AlignedBox2d b;
        for (const auto& body : bodies) {
            const double r = std::max(body.a, body.b);
            b.extend(body.centre - Vec2::Constant(r));
            b.extend(body.centre + Vec2::Constant(r));
        }
        for (const auto& limb : limbs)
            b.extend(limb.box());
        return b;
    }
};

// The boundary of {distance < 0} traced by marching squares on cells of
// `cell` (saddles resolved by the cell centre's value): the loop enclosing
// the largest area, counter-clockwise, one point per crossed grid edge.
template <typename Field>
std::vector<Vec2> traceOutline(const Field& field, const Eigen::AlignedBox2d& box, double cell) {
    const Vec2 origin = box.min() - Vec2::Constant(2 * cell);
    const int nx = static_cast<int>(std::ceil(box.sizes().x() / cell)) + 4;
    const int ny = static_cast<int>(std::ceil(box.sizes().y() / cell)) + 4;
    auto corner = [&](int i, int j) -> Vec2 { return origin + cell * Vec2(i, j); };
    std::vector<double> value(static_cast<std::size_t>(nx + 1) * (ny + 1));
    auto at = [&](int i, int j) -> double& {
        return value[static_cast<std::size_t>(j) * (nx + 1) + i];
    };
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            const double d = field.distance(corner(i, j));
            at(i, j) = d == 0.0 ? 1e-12 : d;  // no corner exactly on the boundary
        }
    // Grid edges by id: horizontal (i,j)-(i+1,j) even, vertical (i,j)-(i,j+1) odd.
    auto horizontal = [&](int i, int j) { return 2 * (std::int64_t(j) * (nx + 1) + i); };
    auto vertical = [&](int i, int j) { return 2 * (std::int64_t(j) * (nx + 1) + i) + 1; };
    std::unordered_map<std::int64_t, Vec2> crossing;
    std::unordered_map<std::int64_t, std::array<std::int64_t, 2>> links;
    auto point = [&](std::int64_t id) {
        auto found = crossing.find(id);
        if (found != crossing.end())
            return;
        const std::int64_t k = id / 2;
        const int i = static_cast<int>(k % (nx + 1)), j = static_cast<int>(k / (nx + 1));
        const int i2 = id % 2 == 0 ? i + 1 : i, j2 = id % 2 == 0 ? j : j + 1;
        const double a = at(i, j), b = at(i2, j2);
        const Vec2 p = corner(i, j) + (a / (a - b)) * (corner(i2, j2) - corner(i, j));
        crossing.emplace(id, p);
    };
    auto link = [&](std::int64_t a, std::int64_t b) {
        point(a);
        point(b);
        for (auto [from, to] : {std::pair{a, b}, {b, a}}) {
            auto& slot = links.try_emplace(from, std::array<std::int64_t, 2>{-1, -1}).first->second;
            (slot[0] < 0 ? slot[0] : slot[1]) = to;
        }
    };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const bool c0 = at(i, j) < 0, c1 = at(i + 1, j) < 0, c2 = at(i + 1, j + 1) < 0,
                       c3 = at(i, j + 1) < 0;
            const std::int64_t e0 = horizontal(i, j), e1 = vertical(i + 1, j),
                               e2 = horizontal(i, j + 1), e3 = vertical(i, j);
            std::vector<std::int64_t> crossed;
            if (c0 != c1)
                crossed.push_back(e0);
            if (c1 != c2)
                crossed.push_back(e1);
            if (c3 != c2)
                crossed.push_back(e2);
            if (c0 != c3)
                crossed.push_back(e3);
            if (crossed.size() == 2) {
                link(crossed[0], crossed[1]);
            } else if (crossed.size() == 4) {
                const bool centreInside =
                    at(i, j) + at(i + 1, j) + at(i + 1, j + 1) + at(i, j + 1) < 0;
                // Cut off the corners not joined through the centre.
                if (centreInside == c0) {  // c0 and c2 joined: cut c1 and c3 off
                    link(e0, e1);
                    link(e2, e3);
                } else {
                    link(e3, e0);
                    link(e1, e2);
                }
            }
        }
    std::vector<Vec2> best;
    double bestArea = 0;
    std::unordered_map<std::int64_t, bool> visited;
    for (const auto& [start, unused] : links) {
        if (visited[start])
            continue;
        std::vector<Vec2> loop;
        std::int64_t previous = -1, current = start;
        while (current >= 0 && !visited[current]) {
            visited[current] = true;
            loop.push_back(crossing.at(current));
            const auto& next = links.at(current);
            const std::int64_t following = next[0] != previous ? next[0] : next[1];
            previous = current;
            current = following;
        }
        const double area = signedArea(loop);
        if (std::abs(area) > bestArea) {
            bestArea = std::abs(area);
            best = std::move(loop);
        }
    }
    if (signedArea(best) < 0)
        std::reverse(best.begin(), best.end());
    return best;
}

}  // namespace rigmesh::testsupport
