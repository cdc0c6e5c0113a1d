// Small hand-built meshes with known topology for the mesh tests.
#pragma once

#include <cmath>
#include <numbers>

#include "mesh/TriMesh.h"

namespace rigmesh::testshapes {

// A closed, outward torus around the z axis: genus 1.
inline TriMesh torus(int around, int tube, double majorRadius, double minorRadius) {
    TriMesh mesh;
    for (int i = 0; i < around; ++i) {
        const double u = 2 * std::numbers::pi * i / around;
        for (int j = 0; j < tube; ++j) {
            const double v = 2 * std::numbers::pi * j / tube;
            const double ring = majorRadius + minorRadius * std::cos(v);
            mesh.vertices.emplace_back(ring * std::cos(u), ring * std::sin(u),
                                       minorRadius * std::sin(v));
        }
    }
    const auto at = [&](int i, int j) { return (i % around) * tube + (j % tube); };
    for (int i = 0; i < around; ++i)
        for (int j = 0; j < tube; ++j) {
            mesh.faces.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            mesh.faces.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    return mesh;
}

// A closed, outward tetrahedron with corners at `origin` and origin + unit axes.
inline TriMesh tetrahedron(const Vec3& origin = Vec3::Zero()) {
    TriMesh mesh;
    mesh.vertices = {origin, origin + Vec3::UnitX(), origin + Vec3::UnitY(),
                     origin + Vec3::UnitZ()};
    mesh.faces = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return mesh;
}

// An axis-aligned box, outward, two triangles a side.
inline TriMesh box(const Vec3& low, const Vec3& high) {
    TriMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.vertices.emplace_back(corner & 1 ? high.x() : low.x(), corner & 2 ? high.y() : low.y(),
                                   corner & 4 ? high.z() : low.z());
    mesh.faces = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                  {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    return mesh;
}

// Appends `part` to `mesh` as a separate piece of the same soup.
// Two cones on a unit circle of `segments` vertices, apexes at z = +-1: each
// apex has `segments` faces around it.
inline TriMesh doubleCone(int segments) {
    TriMesh cone;
    for (int k = 0; k < segments; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / segments;
        cone.vertices.emplace_back(std::cos(angle), std::sin(angle), 0.0);
    }
    const int top = segments, bottom = segments + 1;
    cone.vertices.emplace_back(0.0, 0.0, 1.0);
    cone.vertices.emplace_back(0.0, 0.0, -1.0);
    for (int k = 0; k < segments; ++k) {
        const int next = (k + 1) % segments;
        cone.faces.push_back({k, next, top});
        cone.faces.push_back({next, k, bottom});
    }
    return cone;
}

inline void append(TriMesh& mesh, const TriMesh& part) {
    const int offset = mesh.vertexCount();
    mesh.vertices.insert(mesh.vertices.end(), part.vertices.begin(), part.vertices.end());
    for (const auto& [a, b, c] : part.faces)
        mesh.faces.push_back({a + offset, b + offset, c + offset});
}

}  // namespace rigmesh::testshapes
