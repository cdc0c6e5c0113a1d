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

// What a face does to the ray from `point` along axis `k` (with i, j the
// two other axes in cyclic order): +1 or -1 when the ray leaves through it
// along or against its normal, 0 when the ray misses it, nullopt when the
// ray meets one of its edges or vertices or the point lies on it.
std::optional<int> crossingOf(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& point, int i,
                              int j) {
    // The projection along the ray onto the plane of the two other axes,
    // in cyclic order (i, j, k), so that a left turn there is a face normal
    // with a positive k component.
    const auto along = [&](const Vec3& v) { return Point2(v[i], v[j]); };
    const Point2 q = along(point);
    // The ray's line meets the face's interior where the point's
    // projection lies strictly inside the face's projection; the three
    // orientations then agree with the sign of the normal's k component.
    const CGAL::Orientation ab = CGAL::orientation(along(a), along(b), q);
    const CGAL::Orientation bc = CGAL::orientation(along(b), along(c), q);
    const CGAL::Orientation ca = CGAL::orientation(along(c), along(a), q);
    const bool onBorder = ab == CGAL::COLLINEAR || bc == CGAL::COLLINEAR || ca == CGAL::COLLINEAR;
    if (!onBorder && (ab != bc || bc != ca))
        return 0;  // outside the projection
    if (onBorder) {
        // Strictly outside if two corners' orientations disagree anyway;
        // else the line may graze an edge or a vertex.
        const bool positive =
            ab == CGAL::LEFT_TURN || bc == CGAL::LEFT_TURN || ca == CGAL::LEFT_TURN;
        const bool negative =
            ab == CGAL::RIGHT_TURN || bc == CGAL::RIGHT_TURN || ca == CGAL::RIGHT_TURN;
        if (positive && negative)
            return 0;
        return std::nullopt;
    }
    // Inside the projection: the ray meets the face if the point lies on
    // the side of its plane the ray leaves from. CGAL's orientation of (a,
    // b, c, p) is the sign of ((b - a) x (c - a)) . (p - a): the point lies
    // behind a face whose normal runs with the ray (the projection turns
    // left) when it is negative.
    const CGAL::Orientation side =
        CGAL::orientation(point3(a), point3(b), point3(c), point3(point));
    if (side == CGAL::COPLANAR)
        return std::nullopt;  // on the face
    const bool normalAlongRay = ab == CGAL::LEFT_TURN;
    if (normalAlongRay && side == CGAL::NEGATIVE)
        return 1;  // leaves through the face, along its normal
    if (!normalAlongRay && side == CGAL::POSITIVE)
        return -1;  // leaves through the face, against its normal
    return 0;
}

// The winding numbers counted along the rays from `points[p]` along axis
// `k`, for the points p in `undecided`, in one pass over the faces: each face
// meets only the rays whose points lie within its box across the ray (found
// by a binary search among the points sorted along axis i) and not beyond
// it along the ray. A point whose ray meets an edge or a vertex, or that
// lies on a face, gets nullopt.
void windingsAlong(const TriMesh& mesh, const std::vector<Vec3>& points,
                   const std::vector<int>& undecided, int k,
                   std::vector<std::optional<int>>& windings) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    std::vector<int> order = undecided;
    std::sort(order.begin(), order.end(),
              [&](int a, int b) { return points[a][i] < points[b][i]; });
    std::vector<double> sortedI(order.size());
    for (std::size_t n = 0; n < order.size(); ++n)
        sortedI[n] = points[order[n]][i];
    std::vector<int> winding(points.size(), 0);
    std::vector<char> failed(points.size(), 0);
    for (const auto& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3& b = mesh.vertices[face[1]];
        const Vec3& c = mesh.vertices[face[2]];
        const double lowI = std::min({a[i], b[i], c[i]}), highI = std::max({a[i], b[i], c[i]});
        auto first = std::lower_bound(sortedI.begin(), sortedI.end(), lowI);
        if (first == sortedI.end() || *first > highI)
            continue;
        const double lowJ = std::min({a[j], b[j], c[j]}), highJ = std::max({a[j], b[j], c[j]});
        const double highK = std::max({a[k], b[k], c[k]});
        for (auto it = first; it != sortedI.end() && *it <= highI; ++it) {
            const int p = order[it - sortedI.begin()];
            const Vec3& point = points[p];
            // The ray {point + t e_k, t > 0} cannot meet a face wholly
            // behind the point or beside the ray.
            if (failed[p] || highK < point[k] || highJ < point[j] || lowJ > point[j])
                continue;
            const std::optional<int> crossing = crossingOf(a, b, c, point, i, j);
            if (crossing)
                winding[p] += *crossing;
            else
                failed[p] = 1;
        }
    }
    for (int p : undecided)
        windings[p] = failed[p] ? std::nullopt : std::optional<int>(winding[p]);
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
    return exactWindingNumbers(mesh, {point}).front();
}

std::vector<std::optional<int>> exactWindingNumbers(const TriMesh& mesh,
                                                    const std::vector<Vec3>& points) {
    std::vector<std::optional<int>> windings(points.size());
    std::vector<int> undecided(points.size());
    for (std::size_t p = 0; p < points.size(); ++p)
        undecided[p] = static_cast<int>(p);
    // Along z first: a sketched part lies about the plane z = 0, its joints
    // in it and its silhouette's edges too, so rays along x or y there run
    // along edges; then x, then y, for the points still undecided.
    for (int k : {2, 0, 1}) {
        if (undecided.empty())
            break;
        windingsAlong(mesh, points, undecided, k, windings);
        std::erase_if(undecided, [&](int p) { return windings[p].has_value(); });
    }
    return windings;
}

}  // namespace rigmesh
