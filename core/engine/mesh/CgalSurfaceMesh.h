// CGAL's Surface_mesh at the engine's edge, for the few .cpp files that run
// Polygon Mesh Processing or an AABB tree on a TriMesh (merge/MeshUnion,
// cut/SurfaceSplit, and autorig's MeshRepair, CurveSkeleton, ProxyWrap,
// WeightTransfer and SurfaceProbe): the conversion, exact-position lookup of
// unchanged vertices, and the closest source triangle of a new vertex.
// Include only from .cpp files.
#pragma once

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <Eigen/Geometry>

#include <array>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#include "base/Error.h"
#include "mesh/TriMesh.h"
#include "part/VertexSource.h"

namespace rigmesh::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
using VertexIndex = SurfaceMesh::Vertex_index;
using FaceIndex = SurfaceMesh::Face_index;
using EdgeIndex = SurfaceMesh::Edge_index;

inline Vec3 toVec(const Point& p) {
    return {p.x(), p.y(), p.z()};
}

// `notManifold` and, for a closed surface, `hasHole`: the messages naming
// the surface when it is not one.
inline SurfaceMesh toSurfaceMesh(const TriMesh& mesh, MessageId notManifold,
                                 MessageId hasHole = MessageId::None) {
    const bool closed = hasHole != MessageId::None;
    SurfaceMesh surface;
    surface.reserve(mesh.vertexCount(), mesh.faceCount() * 3 / 2, mesh.faceCount());
    for (const Vec3& v : mesh.vertices)
        surface.add_vertex(Point(v.x(), v.y(), v.z()));
    for (const auto& [a, b, c] : mesh.faces) {
        const FaceIndex f = surface.add_face(VertexIndex(a), VertexIndex(b), VertexIndex(c));
        if (f == SurfaceMesh::null_face())
            throw Error(notManifold);
    }
    if (closed && !CGAL::is_closed(surface))
        throw Error(hasHole);
    return surface;
}

// Exact positions of both inputs: corefinement copies the points of every
// vertex it does not create, so a bitwise match is an unchanged vertex.
struct PointKey {
    std::array<double, 3> xyz;
    bool operator==(const PointKey& other) const { return xyz == other.xyz; }
};
struct PointKeyHash {
    std::size_t operator()(const PointKey& key) const {
        std::size_t h = 0;
        for (double d : key.xyz) {
            std::uint64_t bits;
            std::memcpy(&bits, &d, sizeof bits);
            h ^= std::hash<std::uint64_t>{}(bits) + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        }
        return h;
    }
};
inline PointKey keyOf(const Vec3& p) {
    return {{p.x(), p.y(), p.z()}};
}

inline Vec3 barycentricOf(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 e0 = b - a, e1 = c - a, d = p - a;
    const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
    const double d20 = d.dot(e0), d21 = d.dot(e1);
    const double denominator = d00 * d11 - d01 * d01;
    if (!(std::abs(denominator) > 0.0))
        return {1.0, 0.0, 0.0};
    const double v = (d11 * d20 - d01 * d21) / denominator;
    const double w = (d00 * d21 - d01 * d20) / denominator;
    Vec3 result(1.0 - v - w, v, w);
    result = result.cwiseMax(0.0);
    return result / result.sum();
}

// The closest point of either input's surface, as a triangle source.
class SourceTriangles {
  public:
    explicit SourceTriangles(std::vector<const TriMesh*> meshes) : meshes_(std::move(meshes)) {
        for (int m = 0; m < static_cast<int>(meshes_.size()); ++m)
            for (int f = 0; f < meshes_[m]->faceCount(); ++f) {
                const auto& face = meshes_[m]->faces[f];
                const Vec3& a = meshes_[m]->vertices[face[0]];
                const Vec3& b = meshes_[m]->vertices[face[1]];
                const Vec3& c = meshes_[m]->vertices[face[2]];
                triangles_.emplace_back(Point(a.x(), a.y(), a.z()), Point(b.x(), b.y(), b.z()),
                                        Point(c.x(), c.y(), c.z()));
                owners_.push_back({m, f});
            }
        tree_.insert(triangles_.begin(), triangles_.end());
        tree_.accelerate_distance_queries();
    }

    VertexSource sourceOf(const Vec3& p) const {
        const auto [closest, primitive] =
            tree_.closest_point_and_primitive(Point(p.x(), p.y(), p.z()));
        const auto [mesh, face] = owners_[primitive - triangles_.begin()];
        const auto& corners = meshes_[mesh]->faces[face];
        const auto& v = meshes_[mesh]->vertices;
        return VertexSource::triangle(
            mesh, face, barycentricOf(toVec(closest), v[corners[0]], v[corners[1]], v[corners[2]]));
    }

  private:
    using Triangle = Kernel::Triangle_3;
    using Iterator = std::vector<Triangle>::const_iterator;
    using Primitive = CGAL::AABB_triangle_primitive<Kernel, Iterator>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

    std::vector<const TriMesh*> meshes_;
    std::vector<Triangle> triangles_;
    std::vector<std::pair<int, int>> owners_;
    Tree tree_;
};

}  // namespace rigmesh::cgal
