// A closed, oriented, manifold TriMesh as CGAL's Surface_mesh, built
// directly: the same element indices and connectivity that
// mesh/CgalSurfaceMesh's toSurfaceMesh (CGAL::Euler::add_face, face by face)
// gives, without its per-face searches and checks (an eighth of a cut of the
// camel by perf on bench_merge). Include only from .cpp files: it brings in
// CGAL.
//
// What add_face gives on such a surface, faces added in index order (CGAL
// 5.5, boost/graph/Euler_operations.h):
// - vertex i and face f keep their indices;
// - an edge is made by the first face that has it, in the order of the
//   faces and of their corners, as the pair (2e, 2e + 1): 2e runs as that
//   face runs, 2e + 1 is its opposite;
// - a face's halfedge is the one into its first corner (from its last);
// - a vertex's halfedge is the one into it in the last face around it: while
//   the faces around a vertex leave a gap, add_face keeps the vertex's
//   halfedge on the border (adjust_incoming_halfedge), and the last face
//   fills the gap between two existing edges, the border halfedge into the
//   vertex becoming its own.
// Anything else (a border, a non-manifold edge or vertex, an edge used twice
// the same way, a degenerate face or an isolated vertex) returns nullopt: the
// caller converts with toSurfaceMesh, which names the problem.
#pragma once

#include <optional>
#include <vector>

#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh::cgal {

inline std::optional<SurfaceMesh> closedSurfaceMesh(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    const int faceCount = mesh.faceCount();
    const int corners = 3 * faceCount;
    // Corner slot 3f + c: the halfedge from corner c of face f to corner c + 1.
    auto from = [&](int slot) { return mesh.faces[slot / 3][slot % 3]; };
    auto to = [&](int slot) { return mesh.faces[slot / 3][(slot % 3 + 1) % 3]; };
    std::vector<int> outStart(n + 1, 0);
    for (const auto& face : mesh.faces) {
        for (int c = 0; c < 3; ++c)
            if (face[c] < 0 || face[c] >= n)
                return std::nullopt;
        if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0])
            return std::nullopt;
        for (int v : face)
            ++outStart[v + 1];
    }
    for (int v = 0; v < n; ++v) {
        if (outStart[v + 1] == 0)
            return std::nullopt;  // isolated
        outStart[v + 1] += outStart[v];
    }
    // Each vertex's outgoing halfedges and, beside them, their targets (the
    // searches below read these runs only).
    std::vector<int> outgoing(corners), outTarget(corners);
    {
        std::vector<int> fill(outStart.begin(), outStart.end() - 1);
        for (int slot = 0; slot < corners; ++slot) {
            const int k = fill[from(slot)]++;
            outgoing[k] = slot;
            outTarget[k] = to(slot);
        }
    }
    // Each halfedge once, and its opposite there: closed, oriented and
    // manifold at every edge.
    for (int v = 0; v < n; ++v)
        for (int k = outStart[v]; k < outStart[v + 1]; ++k)
            for (int l = k + 1; l < outStart[v + 1]; ++l)
                if (outTarget[k] == outTarget[l])
                    return std::nullopt;
    std::vector<int> opposite(corners, -1);
    for (int a = 0; a < n; ++a)
        for (int k = outStart[a]; k < outStart[a + 1]; ++k) {
            const int slot = outgoing[k];
            if (opposite[slot] >= 0)
                continue;
            const int b = outTarget[k];
            for (int l = outStart[b]; l < outStart[b + 1]; ++l)
                if (outTarget[l] == a) {
                    opposite[slot] = outgoing[l];
                    opposite[outgoing[l]] = slot;
                    break;
                }
            if (opposite[slot] < 0)
                return std::nullopt;
        }
    // Manifold at every vertex: its faces make one fan (turning around it
    // from one outgoing halfedge reaches them all).
    for (int v = 0; v < n; ++v) {
        const int first = outgoing[outStart[v]];
        int slot = first, steps = 0;
        do {
            // The next outgoing halfedge around v: the opposite of the
            // halfedge into v in the same face.
            slot = opposite[slot % 3 == 0 ? slot + 2 : slot - 1];
            ++steps;
        } while (slot != first && steps <= outStart[v + 1] - outStart[v]);
        if (slot != first || steps != outStart[v + 1] - outStart[v])
            return std::nullopt;
    }

    // Halfedge indices as add_face makes them.
    std::vector<int> halfedge(corners, -1);
    int edges = 0;
    for (int slot = 0; slot < corners; ++slot)
        if (halfedge[slot] < 0) {
            halfedge[slot] = 2 * edges;
            halfedge[opposite[slot]] = 2 * edges + 1;
            ++edges;
        }

    // Every element at once: resize() gives each property the default value
    // that add_vertex, add_edge and add_face push one by one (CGAL 5.5,
    // Surface_mesh/Surface_mesh.h; they were two fifths of this function by
    // perf on bench_merge's curved camel cut).
    SurfaceMesh surface;
    surface.resize(n, edges, faceCount);
    for (int v = 0; v < n; ++v) {
        const Vec3& p = mesh.vertices[v];
        surface.point(VertexIndex(v)) = Point(p.x(), p.y(), p.z());
    }
    using HalfedgeIndex = SurfaceMesh::Halfedge_index;
    for (int slot = 0; slot < corners; ++slot) {
        const int f = slot / 3;
        const HalfedgeIndex h(halfedge[slot]);
        surface.set_target(h, VertexIndex(to(slot)));
        surface.set_face(h, FaceIndex(f));
        surface.set_next(h, HalfedgeIndex(halfedge[slot % 3 == 2 ? slot - 2 : slot + 1]));
        surface.set_halfedge(VertexIndex(to(slot)), h);  // the last face's wins
    }
    for (int f = 0; f < faceCount; ++f)
        surface.set_halfedge(FaceIndex(f), HalfedgeIndex(halfedge[3 * f + 2]));
    return surface;
}

}  // namespace rigmesh::cgal
