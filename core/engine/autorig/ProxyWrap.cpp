#include "autorig/ProxyWrap.h"

#include <CGAL/alpha_wrap_3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <tuple>
#include <utility>

#include "base/Error.h"
#include "mesh/CgalSurfaceMesh.h"
#include "mesh/MeshTopologyCheck.h"

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
// A wrap tried again finer continues the bar from where it stood (`start`).
struct WrapVisitor : CGAL::Alpha_wraps_3::internal::Wrapping_default_visitor {
    const RigProgress* progress = nullptr;
    double expected = 1.0;
    double start = 0.0;
    long inserted = 0;

    template <typename Wrapper, typename Point3>
    void before_Steiner_point_insertion(const Wrapper&, const Point3&) {
        if (++inserted % 64 == 0)
            reportRigProgress(*progress, reached());
    }
    double reached() const { return start + (1.0 - start) * std::min(0.95, inserted / expected); }
};

// The handles (genus summed over components) of a closed wrap, 2 c - chi =
// 2 g, and its components.
std::pair<int, int> handlesAndComponentsOf(const TriMesh& wrap) {
    const MeshReport report = analyseMeshTopology(wrap);
    return {std::max(0, (2 * report.components - report.eulerCharacteristic) / 2),
            report.components};
}

// One wrap of `soup` at `alpha` (offset and sampling from the options).
ProxyWrapResult wrapAt(const TriMesh& soup, double alpha, const ProxyWrapOptions& options,
                       WrapVisitor& visitor) {
    ProxyWrapResult result;
    result.alpha = alpha;
    result.offset = alpha * options.offsetFraction;
    const std::vector<Point> points = surfaceSamples(soup, alpha * options.sampleFraction);
    result.wrappedPoints = static_cast<int>(points.size());
    if (points.size() < 4)
        throw Error(MessageId::AutoRigTooFewFaces, soup.faceCount());
    visitor.inserted = 0;
    visitor.expected = std::max(1.0, kVerticesPerArea * areaOf(soup) / (alpha * alpha));
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
    std::tie(result.handles, result.components) = handlesAndComponentsOf(result.mesh);
    return result;
}

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
    const double alpha = chooseWrapAlpha(soup, options);
    if (!(alpha > 0.0))
        throw Error(MessageId::AutoRigTooFewFaces, soup.faceCount());
    WrapVisitor visitor;
    const RigProgress noProgress = [](double) { return true; };
    visitor.progress = progress ? &progress : &noProgress;
    ProxyWrapResult result = wrapAt(soup, alpha, options, visitor);

    // A handle the wrap has may be a gap narrower than alpha it bridged: two
    // legs joined at the soles make a loop leg - body - leg that the input's
    // pieces do not close. One wrap finer (twice the vertices) is tried, and
    // kept when it has fewer handles and no more components. A handle of the
    // shape itself (a torus, a hand on a hip) stays; going finer still costs
    // a wrap of four times the vertices and more per step, and the spider of
    // assimp-testmodels, whose first wrap has two handles, came out of those
    // finer wraps with thinner legs and worse bones (docs/ARCHITECTURE.md 2d).
    const double finest = options.finestAlpha * boundsOf(soup).diagonal().norm();
    if (result.handles > 0 && alpha > finest) {
        visitor.start = visitor.reached();
        ProxyWrapResult finer =
            wrapAt(soup, std::max(alpha * options.handleRetryFactor, finest), options, visitor);
        const bool better = finer.handles < result.handles && finer.components <= result.components;
        if (better)
            result = std::move(finer);
        result.wraps = 2;
    }
    reportRigProgress(progress, 1.0);
    return result;
}

}  // namespace rigmesh
