#include "mesh/ExactWinding.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace rigmesh {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point2 = Kernel::Point_2;
using Point3 = Kernel::Point_3;

Point3 point3(const Vec3& v) {
    return {v.x(), v.y(), v.z()};
}

// The projection along x (the ray's direction) onto the (y, z) plane.
Point2 alongX(const Vec3& v) {
    return {v.y(), v.z()};
}

}  // namespace

bool directedEdgesCancel(const TriMesh& mesh) {
    // Edge uses bucketed by their smaller vertex (a counting sort), each
    // bucket's uses summed per larger vertex: +1 for a->b with a < b, -1 for
    // b->a.
    const int n = mesh.vertexCount();
    std::vector<int> start(static_cast<std::size_t>(n) + 1, 0);
    for (const auto& face : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = face[k], b = face[(k + 1) % 3];
            if (a < 0 || b < 0 || a >= n || b >= n || a == b)
                return false;
            ++start[std::min(a, b) + 1];
        }
    for (int v = 0; v < n; ++v)
        start[v + 1] += start[v];
    std::vector<std::int64_t> uses(start.back());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& face : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = face[k], b = face[(k + 1) % 3];
            // The larger vertex and the direction in one number: 2 b + 1 for
            // a->b (a < b), 2 a for b->a.
            uses[fill[std::min(a, b)]++] = a < b ? 2 * std::int64_t(b) + 1 : 2 * std::int64_t(a);
        }
    for (int v = 0; v < n; ++v) {
        const auto first = uses.begin() + start[v], last = uses.begin() + start[v + 1];
        std::sort(first, last);
        for (auto it = first; it != last;) {
            const std::int64_t other = *it / 2;
            int sum = 0;
            for (; it != last && *it / 2 == other; ++it)
                sum += (*it % 2) ? 1 : -1;
            if (sum != 0)
                return false;
        }
    }
    return true;
}

std::optional<int> exactWindingNumber(const TriMesh& mesh, const Vec3& point) {
    const Point2 q = alongX(point);
    const Point3 p = point3(point);
    int winding = 0;
    for (const auto& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3& b = mesh.vertices[face[1]];
        const Vec3& c = mesh.vertices[face[2]];
        // The ray {point + t x, t > 0} cannot meet a face wholly behind the
        // point or beside the ray.
        if (std::max({a.x(), b.x(), c.x()}) < point.x() ||
            std::max({a.y(), b.y(), c.y()}) < point.y() ||
            std::min({a.y(), b.y(), c.y()}) > point.y() ||
            std::max({a.z(), b.z(), c.z()}) < point.z() ||
            std::min({a.z(), b.z(), c.z()}) > point.z())
            continue;
        // The ray's line meets the face's interior where the point's
        // projection along x lies strictly inside the face's projection;
        // the three orientations then agree with the sign of the face
        // normal's x component.
        const CGAL::Orientation ab = CGAL::orientation(alongX(a), alongX(b), q);
        const CGAL::Orientation bc = CGAL::orientation(alongX(b), alongX(c), q);
        const CGAL::Orientation ca = CGAL::orientation(alongX(c), alongX(a), q);
        const bool onBorder =
            ab == CGAL::COLLINEAR || bc == CGAL::COLLINEAR || ca == CGAL::COLLINEAR;
        if (!onBorder && (ab != bc || bc != ca))
            continue;  // outside the projection
        if (onBorder) {
            // Strictly outside if two corners' orientations disagree anyway;
            // else the line may graze an edge or a vertex.
            const bool positive =
                ab == CGAL::LEFT_TURN || bc == CGAL::LEFT_TURN || ca == CGAL::LEFT_TURN;
            const bool negative =
                ab == CGAL::RIGHT_TURN || bc == CGAL::RIGHT_TURN || ca == CGAL::RIGHT_TURN;
            if (positive && negative)
                continue;
            return std::nullopt;
        }
        // Inside the projection: the ray meets the face if the point lies
        // on the side of its plane the ray leaves from. CGAL's orientation
        // of (a, b, c, p) is the sign of ((b - a) x (c - a)) . (p - a): the
        // point lies behind a face whose normal runs with x (the projection
        // turns left) when it is negative, and the ray leaves through it.
        const CGAL::Orientation side = CGAL::orientation(point3(a), point3(b), point3(c), p);
        if (side == CGAL::COPLANAR)
            return std::nullopt;  // on the face
        const bool normalAlongRay = ab == CGAL::LEFT_TURN;
        if (normalAlongRay && side == CGAL::NEGATIVE)
            ++winding;  // leaves through the face, along its normal
        else if (!normalAlongRay && side == CGAL::POSITIVE)
            --winding;  // leaves through the face, against its normal
    }
    return winding;
}

}  // namespace rigmesh
