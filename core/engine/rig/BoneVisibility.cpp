#include "rig/BoneVisibility.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

#include "base/Error.h"

namespace rigmesh {

namespace {

// Exact predicates: a segment grazing an edge is classified consistently.
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;
using TriangleIterator = std::vector<Triangle>::const_iterator;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, TriangleIterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point toPoint(const Vec3& p) {
    return Point(p.x(), p.y(), p.z());
}

// How far along the segment the test starts, relative to its length, so that
// the triangles around the starting vertex are not counted as crossings.
constexpr double kStartOffset = 1e-6;

// Pinocchio's vectorInCone: the direction from the bone point to the vertex
// must lie within 60 degrees of the vertex normal.
constexpr double kConeCosine = 0.5;

}  // namespace

struct BoneVisibility::Tree {
    std::vector<Triangle> triangles;  // the tree refers into this vector
    AabbTree tree;
};

BoneVisibility::BoneVisibility(const TriMesh& mesh) : tree_(std::make_unique<Tree>()) {
    tree_->triangles.reserve(mesh.faces.size());
    for (const auto& face : mesh.faces) {
        for (int corner : face) {
            if (corner < 0 || corner >= mesh.vertexCount()) {
                throw Error(MessageId::MeshTriangleMissingVertex);
            }
        }
        const Triangle triangle(toPoint(mesh.vertices[face[0]]), toPoint(mesh.vertices[face[1]]),
                                toPoint(mesh.vertices[face[2]]));
        // Degenerate triangles bound no volume and break CGAL's predicates.
        if (!triangle.is_degenerate()) {
            tree_->triangles.push_back(triangle);
        }
    }
    tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
    // Build now: the lazy build on first query is not thread-safe.
    tree_->tree.build();
}

BoneVisibility::~BoneVisibility() = default;
BoneVisibility::BoneVisibility(BoneVisibility&&) noexcept = default;
BoneVisibility& BoneVisibility::operator=(BoneVisibility&&) noexcept = default;

bool BoneVisibility::segmentIsInside(const Vec3& from, const Vec3& to) const {
    const Vec3 start = from + kStartOffset * (to - from);
    if (!start.allFinite() || !to.allFinite()) {
        return false;
    }
    if (start == to || tree_->triangles.empty()) {
        return true;
    }
    return !tree_->tree.do_intersect(Kernel::Segment_3(toPoint(start), toPoint(to)));
}

std::vector<std::vector<std::pair<int, double>>> closestVisibleBones(
    const TriMesh& mesh, const std::vector<BoneSegment>& bones, const BoneVisibility& visibility,
    const std::vector<int>& verticesToTest, double tieTolerance, int* verticesWithoutVisibleBone) {
    // Area-weighted vertex normals from the CCW outward triangles.
    std::vector<Vec3> normals(mesh.vertices.size(), Vec3::Zero());
    for (const auto& face : mesh.faces) {
        const Vec3& a = mesh.vertices[face[0]];
        const Vec3 n = (mesh.vertices[face[1]] - a).cross(mesh.vertices[face[2]] - a);
        for (int corner : face) {
            normals[corner] += n;
        }
    }

    std::vector<std::vector<std::pair<int, double>>> result(verticesToTest.size());
    std::vector<std::pair<double, int>> byDistance;
    int withoutVisible = 0;
    for (std::size_t t = 0; t < verticesToTest.size(); ++t) {
        const int v = verticesToTest[t];
        if (v < 0 || v >= mesh.vertexCount()) {
            throw std::logic_error("A vertex to test for bone visibility is not in the mesh.");
        }
        const Vec3& position = mesh.vertices[v];

        byDistance.clear();
        for (int b = 0; b < static_cast<int>(bones.size()); ++b) {
            const double d = pointSegmentDistance(position, bones[b]);
            if (std::isfinite(d)) {
                byDistance.emplace_back(d, b);
            }
        }
        std::sort(byDistance.begin(), byDistance.end());

        // Walk the bones nearest first; once one is visible, keep only the
        // visible ones that tie with it (Pinocchio factors in equally close
        // bones so that neither wins arbitrarily).
        auto& chosen = result[t];
        const Vec3 normal = normals[v].normalized();
        for (const auto& [d, b] : byDistance) {
            if (!chosen.empty() && d > chosen.front().second * (1.0 + tieTolerance)) {
                break;
            }
            const Vec3 p = closestPointOnSegment(position, bones[b]);
            const Vec3 outward = position - p;
            const bool inCone =
                outward.norm() == 0.0 || outward.dot(normal) > kConeCosine * outward.norm();
            if (inCone && visibility.segmentIsInside(position, p)) {
                chosen.emplace_back(b, d);
            }
        }
        if (chosen.empty() && !byDistance.empty()) {
            ++withoutVisible;
            const double nearest = byDistance.front().first;
            for (const auto& [d, b] : byDistance) {
                if (d > nearest * (1.0 + tieTolerance)) {
                    break;
                }
                chosen.emplace_back(b, d);
            }
        }
    }
    if (verticesWithoutVisibleBone != nullptr) {
        *verticesWithoutVisibleBone = withoutVisible;
    }
    return result;
}

}  // namespace rigmesh
