#include "mesh/SurfaceQuality.h"
#include "base/Statistics.h"
#include "sketch/PolygonGeometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include <Eigen/Geometry>

namespace rigmesh {
namespace {

std::uint64_t edgeKey(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

}  // namespace

NormalAngles normalAngles(const TriMesh& mesh) {
    std::vector<Vec3> normals;
    normals.reserve(mesh.faces.size());
    for (const auto& f : mesh.faces) {
        const Vec3 n = (mesh.vertices[static_cast<std::size_t>(f[1])] -
                        mesh.vertices[static_cast<std::size_t>(f[0])])
                           .cross(mesh.vertices[static_cast<std::size_t>(f[2])] -
                                  mesh.vertices[static_cast<std::size_t>(f[0])]);
        normals.push_back(n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero());
    }
    // Per edge: its faces (a third marks a non-manifold edge).
    std::unordered_map<std::uint64_t, std::array<int, 3>> faces;
    faces.reserve(3 * mesh.faces.size() / 2);
    for (int f = 0; f < mesh.faceCount(); ++f)
        for (int k = 0; k < 3; ++k) {
            const auto& face = mesh.faces[static_cast<std::size_t>(f)];
            auto& slot = faces
                             .try_emplace(edgeKey(face[static_cast<std::size_t>(k)],
                                                  face[static_cast<std::size_t>((k + 1) % 3)]),
                                          std::array<int, 3>{-1, -1, -1})
                             .first->second;
            for (int& s : slot)
                if (s < 0) {
                    s = f;
                    break;
                }
        }
    NormalAngles out;
    std::vector<double> angles;
    for (const auto& [key, pair] : faces) {
        if (pair[1] < 0 || pair[2] >= 0)
            continue;
        const Vec3& a = normals[static_cast<std::size_t>(pair[0])];
        const Vec3& b = normals[static_cast<std::size_t>(pair[1])];
        if (a.isZero() || b.isZero())
            continue;
        const double angle = std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
        angles.push_back(angle);
        if (angle > out.max) {
            out.max = angle;
            out.worstEdgeMidpoint =
                0.5 * (mesh.vertices[key >> 32] + mesh.vertices[key & 0xFFFFFFFFu]);
        }
    }
    out.edges = static_cast<int>(angles.size());
    out.p50 = percentile(angles, 0.50);
    out.p99 = percentile(angles, 0.99);
    return out;
}

double silhouetteIoU(const TriMesh& mesh, const std::vector<Vec2>& outline, int resolution) {
    if (mesh.faces.empty() || outline.size() < 3 || resolution < 2)
        return 0;
    Eigen::AlignedBox2d box;
    for (const Vec3& v : mesh.vertices)
        box.extend(Vec2(v.x(), v.y()));
    for (const Vec2& p : outline)
        box.extend(p);
    const Vec2 size = box.sizes();
    const double cell = std::max(size.x(), size.y()) / resolution;
    if (!(cell > 0))
        return 0;
    const int nx = static_cast<int>(std::ceil(size.x() / cell)) + 1;
    const int ny = static_cast<int>(std::ceil(size.y() / cell)) + 1;
    auto centre = [&](int i, int j) {
        return Vec2(box.min().x() + (i + 0.5) * cell, box.min().y() + (j + 0.5) * cell);
    };
    // The mesh's silhouette: every cell centre inside a projected triangle.
    std::vector<char> shadow(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny), 0);
    for (const auto& f : mesh.faces) {
        Vec2 p[3];
        for (int k = 0; k < 3; ++k) {
            const Vec3& v = mesh.vertices[static_cast<std::size_t>(f[static_cast<std::size_t>(k)])];
            p[k] = Vec2(v.x(), v.y());
        }
        const double area =
            (p[1] - p[0]).x() * (p[2] - p[0]).y() - (p[1] - p[0]).y() * (p[2] - p[0]).x();
        if (area == 0)
            continue;
        Eigen::AlignedBox2d triangle;
        for (const Vec2& q : p)
            triangle.extend(q);
        const int i0 =
            std::max(0, static_cast<int>((triangle.min().x() - box.min().x()) / cell) - 1);
        const int i1 =
            std::min(nx - 1, static_cast<int>((triangle.max().x() - box.min().x()) / cell) + 1);
        const int j0 =
            std::max(0, static_cast<int>((triangle.min().y() - box.min().y()) / cell) - 1);
        const int j1 =
            std::min(ny - 1, static_cast<int>((triangle.max().y() - box.min().y()) / cell) + 1);
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const Vec2 c = centre(i, j);
                bool in = true;
                for (int k = 0; k < 3 && in; ++k) {
                    const Vec2 e = p[(k + 1) % 3] - p[k], d = c - p[k];
                    in = (e.x() * d.y() - e.y() * d.x()) * area >= 0;
                }
                if (in)
                    shadow[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
                           static_cast<std::size_t>(i)] = 1;
            }
    }
    long both = 0, either = 0;
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            const Vec2 c = centre(i, j);
            const bool a = shadow[static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) +
                                  static_cast<std::size_t>(i)] != 0;
            const bool b = insidePolygon(outline, c);
            both += a && b ? 1 : 0;
            either += a || b ? 1 : 0;
        }
    return either > 0 ? static_cast<double>(both) / static_cast<double>(either) : 0;
}

}  // namespace rigmesh
