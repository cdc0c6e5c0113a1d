#include "autorig/ProxyWrap.h"

#include <CGAL/alpha_wrap_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

namespace {

using cgal::Point;
using cgal::SurfaceMesh;

// Output vertices per (area / alpha^2), measured on wraps of the assimp
// test characters' sampled points at alpha = diagonal / 55, offset alpha /
// 10 (1.1 for the human, 1.3 for the spider's thin legs).
constexpr double kVerticesPerArea = 1.2;

bool usable(const std::array<int, 3>& face, int vertices) {
    for (int corner : face)
        if (corner < 0 || corner >= vertices)
            return false;
    return face[0] != face[1] && face[1] != face[2] && face[0] != face[2];
}

Eigen::AlignedBox3d boundsOf(const TriMesh& soup) {
    Eigen::AlignedBox3d box;
    for (const auto& face : soup.faces)
        if (usable(face, soup.vertexCount()))
            for (int corner : face)
                box.extend(soup.vertices[corner]);
    return box;
}

double areaOf(const TriMesh& soup) {
    double area = 0.0;
    for (const auto& face : soup.faces)
        if (usable(face, soup.vertexCount()))
            area += 0.5 * (soup.vertices[face[1]] - soup.vertices[face[0]])
                              .cross(soup.vertices[face[2]] - soup.vertices[face[0]])
                              .norm();
    return area;
}

// Points on every triangle, no two in one grid cell of `spacing`: the
// corners and, on a triangle longer than the spacing, a barycentric grid
// of that step. Wrapping points instead of triangles halves the wrap's
// time (measured on the assimp human and spider, same alpha): its distance
// and intersection queries are the cost. The ball cannot pass between
// points closer than alpha, so the wrap does not leak through the surface.
std::vector<Point> surfaceSamples(const TriMesh& soup, double spacing) {
    std::map<std::array<long long, 3>, Vec3> cells;
    const auto add = [&](const Vec3& p) {
        cells.emplace(std::array<long long, 3>{static_cast<long long>(std::floor(p.x() / spacing)),
                                               static_cast<long long>(std::floor(p.y() / spacing)),
                                               static_cast<long long>(std::floor(p.z() / spacing))},
                      p);
    };
    for (const auto& face : soup.faces) {
        if (!usable(face, soup.vertexCount()))
            continue;
        const Vec3& a = soup.vertices[face[0]];
        const Vec3& b = soup.vertices[face[1]];
        const Vec3& c = soup.vertices[face[2]];
        const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
        const int steps = std::max(1, static_cast<int>(std::ceil(longest / spacing)));
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; i + j <= steps; ++j) {
                const double u = static_cast<double>(i) / steps;
                const double v = static_cast<double>(j) / steps;
                add((1.0 - u - v) * a + u * b + v * c);
            }
    }
    std::vector<Point> points;
    points.reserve(cells.size());
    for (const auto& [cell, p] : cells)
        points.emplace_back(p.x(), p.y(), p.z());
    return points;
}

// Told of every point the wrap inserts: reports progress against the
// expected vertex count and stops the wrap when the user cancels.
struct WrapVisitor : CGAL::Alpha_wraps_3::internal::Wrapping_default_visitor {
    const RigProgress* progress = nullptr;
    double expected = 1.0;
    long inserted = 0;

    template <typename Wrapper, typename Point3>
    void before_Steiner_point_insertion(const Wrapper&, const Point3&) {
        if (++inserted % 64 == 0)
            reportRigProgress(*progress, std::min(0.95, inserted / expected));
    }
};

}  // namespace

double chooseWrapAlpha(const TriMesh& soup, const ProxyWrapOptions& options) {
    const Eigen::AlignedBox3d box = boundsOf(soup);
    const double diagonal = box.isEmpty() ? 0.0 : box.diagonal().norm();
    const double alpha =
        std::sqrt(kVerticesPerArea * areaOf(soup) / std::max(1, options.targetVertices));
    return std::clamp(alpha, options.finestAlpha * diagonal, options.coarsestAlpha * diagonal);
}

ProxyWrapResult wrapIntoProxy(const TriMesh& soup, const ProxyWrapOptions& options,
                              const RigProgress& progress) {
    reportRigProgress(progress, 0.0);
    ProxyWrapResult result;
    result.alpha = chooseWrapAlpha(soup, options);
    result.offset = result.alpha * options.offsetFraction;
    if (!(result.alpha > 0.0))
        throw Error(MessageId::AutoRigTooFewFaces, soup.faceCount());
    const std::vector<Point> points = surfaceSamples(soup, result.alpha * options.sampleFraction);
    result.wrappedPoints = static_cast<int>(points.size());
    if (points.size() < 4)
        throw Error(MessageId::AutoRigTooFewFaces, soup.faceCount());

    WrapVisitor visitor;
    const RigProgress noProgress = [](double) { return true; };
    visitor.progress = progress ? &progress : &noProgress;
    visitor.expected =
        std::max(1.0, kVerticesPerArea * areaOf(soup) / (result.alpha * result.alpha));
    SurfaceMesh wrap;
    CGAL::alpha_wrap_3(points, result.alpha, result.offset, wrap,
                       CGAL::parameters::default_values(), CGAL::parameters::visitor(visitor));

    // The wrap comes without garbage: its vertex indices run 0 .. n-1.
    for (auto v : wrap.vertices())
        result.mesh.vertices.push_back(cgal::toVec(wrap.point(v)));
    for (auto f : wrap.faces()) {
        std::array<int, 3> face{};
        int corner = 0;
        for (auto v : CGAL::vertices_around_face(wrap.halfedge(f), wrap))
            face[corner++] = static_cast<int>(v.idx());
        result.mesh.faces.push_back(face);
    }
    reportRigProgress(progress, 1.0);
    return result;
}

}  // namespace rigmesh
