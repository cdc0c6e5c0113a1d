#include "mesh/MeshPrimitives.h"

#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace rigmesh {

namespace {

constexpr int kMaxIcosphereSubdivisions = 8;  // 1.3M faces; more is surely a mistake

// Index of the vertex halfway between a and b on the sphere, created once per edge.
int midpoint(TriMesh& mesh, std::unordered_map<std::uint64_t, int>& cache, int a, int b,
             double radius) {
    const auto lo = static_cast<std::uint64_t>(std::min(a, b));
    const auto hi = static_cast<std::uint64_t>(std::max(a, b));
    const std::uint64_t key = (lo << 32) | hi;
    if (const auto it = cache.find(key); it != cache.end())
        return it->second;
    const Vec3 p = (mesh.vertices[a] + mesh.vertices[b]).normalized() * radius;
    mesh.vertices.push_back(p);
    const int index = mesh.vertexCount() - 1;
    cache.emplace(key, index);
    return index;
}

}  // namespace

TriMesh makeIcosphere(int subdivisions, double radius) {
    if (subdivisions < 0 || subdivisions > kMaxIcosphereSubdivisions)
        throw std::logic_error("Icosphere subdivisions must be between 0 and " +
                               std::to_string(kMaxIcosphereSubdivisions) + ", got " +
                               std::to_string(subdivisions) + ".");
    if (!(radius > 0))
        throw std::logic_error("Icosphere radius must be positive.");

    // The icosahedron: vertices on three orthogonal golden rectangles.
    const double t = std::numbers::phi;
    TriMesh mesh;
    for (const Vec3& v : {Vec3(-1, t, 0), Vec3(1, t, 0), Vec3(-1, -t, 0), Vec3(1, -t, 0),
                          Vec3(0, -1, t), Vec3(0, 1, t), Vec3(0, -1, -t), Vec3(0, 1, -t),
                          Vec3(t, 0, -1), Vec3(t, 0, 1), Vec3(-t, 0, -1), Vec3(-t, 0, 1)})
        mesh.vertices.push_back(v.normalized() * radius);
    mesh.faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                  {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                  {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                  {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};

    // Split every triangle into four, keeping the counter-clockwise order.
    for (int level = 0; level < subdivisions; ++level) {
        std::unordered_map<std::uint64_t, int> cache;
        std::vector<std::array<int, 3>> faces;
        faces.reserve(mesh.faces.size() * 4);
        for (const auto& [a, b, c] : mesh.faces) {
            const int ab = midpoint(mesh, cache, a, b, radius);
            const int bc = midpoint(mesh, cache, b, c, radius);
            const int ca = midpoint(mesh, cache, c, a, radius);
            faces.push_back({a, ab, ca});
            faces.push_back({b, bc, ab});
            faces.push_back({c, ca, bc});
            faces.push_back({ab, bc, ca});
        }
        mesh.faces = std::move(faces);
    }
    return mesh;
}

TriMesh makeCylinderTube(int rings, int segments, double radius, double length) {
    if (rings < 2 || segments < 3)
        throw std::logic_error("A cylinder needs at least 2 rings and 3 segments, got " +
                               std::to_string(rings) + " rings and " + std::to_string(segments) +
                               " segments.");
    if (!(radius > 0) || !(length > 0))
        throw std::logic_error("Cylinder radius and length must be positive.");

    TriMesh mesh;
    mesh.vertices.reserve(static_cast<std::size_t>(rings) * segments + 2);
    for (int r = 0; r < rings; ++r) {
        const double z = -length / 2 + length * r / (rings - 1);
        for (int s = 0; s < segments; ++s) {
            const double angle = 2 * std::numbers::pi * s / segments;
            mesh.vertices.emplace_back(radius * std::cos(angle), radius * std::sin(angle), z);
        }
    }
    const auto ringVertex = [segments](int r, int s) { return r * segments + s % segments; };

    // Side: two triangles per quad, counter-clockwise seen from outside.
    for (int r = 0; r + 1 < rings; ++r) {
        for (int s = 0; s < segments; ++s) {
            const int a = ringVertex(r, s), b = ringVertex(r, s + 1);
            const int c = ringVertex(r + 1, s + 1), d = ringVertex(r + 1, s);
            mesh.faces.push_back({a, b, c});
            mesh.faces.push_back({a, c, d});
        }
    }

    // Caps: a fan around a centre vertex, facing -z at the bottom and +z at the top.
    const int bottom = mesh.vertexCount();
    mesh.vertices.emplace_back(0, 0, -length / 2);
    const int top = mesh.vertexCount();
    mesh.vertices.emplace_back(0, 0, length / 2);
    for (int s = 0; s < segments; ++s) {
        mesh.faces.push_back({bottom, ringVertex(0, s + 1), ringVertex(0, s)});
        mesh.faces.push_back({top, ringVertex(rings - 1, s), ringVertex(rings - 1, s + 1)});
    }
    return mesh;
}

}  // namespace rigmesh
