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

// The winding number counted along the ray from `point` along axis `k`;
// empty when the ray meets an edge or a vertex or the point is on a face.
std::optional<int> windingAlong(const TriMesh& mesh, const Vec3& point, int k) {
    // The projection along the ray onto the plane of the two other axes,
    // in cyclic order (i, j, k), so that a left turn there is a face normal
    // with a positive k component.
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    const auto along = [&](const Vec3& v) { return Point2(v[i], v[j]); };
    const Point2 q = along(point);
    const Point3 p = point3(point);
    int winding = 0;
    for (const auto& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3& b = mesh.vertices[face[1]];
        const Vec3& c = mesh.vertices[face[2]];
        // The ray {point + t e_k, t > 0} cannot meet a face wholly behind
        // the point or beside the ray.
        if (std::max({a[k], b[k], c[k]}) < point[k] || std::max({a[i], b[i], c[i]}) < point[i] ||
            std::min({a[i], b[i], c[i]}) > point[i] || std::max({a[j], b[j], c[j]}) < point[j] ||
            std::min({a[j], b[j], c[j]}) > point[j])
            continue;
        // The ray's line meets the face's interior where the point's
        // projection lies strictly inside the face's projection; the three
        // orientations then agree with the sign of the normal's k component.
        const CGAL::Orientation ab = CGAL::orientation(along(a), along(b), q);
        const CGAL::Orientation bc = CGAL::orientation(along(b), along(c), q);
        const CGAL::Orientation ca = CGAL::orientation(along(c), along(a), q);
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
        // point lies behind a face whose normal runs with the ray (the
        // projection turns left) when it is negative.
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
    // Along z first: a sketched part lies about the plane z = 0, its joints
    // in it and its silhouette's edges too, so rays along x or y there run
    // along edges; then x, then y.
    for (int k : {2, 0, 1})
        if (const std::optional<int> winding = windingAlong(mesh, point, k))
            return winding;
    return std::nullopt;
}

}  // namespace rigmesh
