// Both union scopes (merge/MeshUnion.h) on one pair of surfaces: the near
// union gives the whole union's mesh (faces, loop and sources the same,
// positions but for the rounding of edge-on-edge crossing points), or the
// same refusal.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <optional>
#include <string>

#include "base/Error.h"
#include "merge/MeshUnion.h"
#include "mesh/MeshChecks.h"

namespace rigmesh::testsupport {

// The point a vertex source names on the inputs.
inline Vec3 sourcePoint(const VertexSource& source, const std::array<const TriMesh*, 2>& inputs) {
    const TriMesh& mesh = *inputs[source.mesh];
    if (source.kind == VertexSource::Kind::Vertex)
        return mesh.vertices[source.index];
    const auto& face = mesh.faces[source.index];
    return source.barycentric[0] * mesh.vertices[face[0]] +
           source.barycentric[1] * mesh.vertices[face[1]] +
           source.barycentric[2] * mesh.vertices[face[2]];
}

// The same faces, loop and sources; positions equal but where CGAL rounded
// a point where an edge crosses an edge (merge/NearOverlapUnion.h), within
// `tolerance`; a new vertex's source names the same point within it (on an
// edge it may name either triangle beside it). Returns how many vertices'
// positions differ at all.
inline int expectSameUnion(const MeshUnionResult& near, const MeshUnionResult& whole,
                           const std::array<const TriMesh*, 2>& inputs, double tolerance,
                           const std::string& label) {
    EXPECT_EQ(near.mesh.faces, whole.mesh.faces) << label;
    EXPECT_EQ(near.loop, whole.loop) << label;
    EXPECT_EQ(near.onLoop, whole.onLoop) << label;
    EXPECT_EQ(near.remeshedVertices, whole.remeshedVertices) << label;
    EXPECT_EQ(near.mesh.vertices.size(), whole.mesh.vertices.size()) << label;
    int moved = 0;
    for (std::size_t v = 0; v < near.mesh.vertices.size() && v < whole.mesh.vertices.size(); ++v) {
        const VertexSource& a = near.sources[v];
        const VertexSource& b = whole.sources[v];
        moved += near.mesh.vertices[v] != whole.mesh.vertices[v];
        EXPECT_LE((near.mesh.vertices[v] - whole.mesh.vertices[v]).norm(), tolerance)
            << label << " vertex " << v;
        EXPECT_EQ(a.kind, b.kind) << label << " vertex " << v;
        if (a.kind == VertexSource::Kind::Vertex && b.kind == VertexSource::Kind::Vertex) {
            EXPECT_EQ(a.mesh, b.mesh) << label << " vertex " << v;
            EXPECT_EQ(a.index, b.index) << label << " vertex " << v;
        } else if (a.kind == VertexSource::Kind::Triangle && b.kind == a.kind) {
            EXPECT_LE((sourcePoint(a, inputs) - sourcePoint(b, inputs)).norm(), tolerance)
                << label << " vertex " << v;
        }
    }
    return moved;
}

// Both scopes on one pair: the same mesh (expectSameUnion, positions within
// 1e-13 of the parts' size), or the same refusal. Returns how many vertices'
// positions differ at all.
inline int expectBothScopesAgree(const TriMesh& first, const TriMesh& second, double edge,
                                 const std::string& label) {
    std::optional<MeshUnionResult> whole;
    MessageId wholeRefusal = MessageId::None;
    try {
        whole = unionMeshes(first, second, edge, UnionScope::Whole);
    } catch (const Error& e) {
        wholeRefusal = e.message().id;
    }
    try {
        const MeshUnionResult near = unionMeshes(first, second, edge, UnionScope::NearOverlap);
        EXPECT_TRUE(whole) << label << ": only the near union answers";
        if (!whole)
            return 0;
        const double size = boundingBox(first).merged(boundingBox(second)).diagonal().norm();
        return expectSameUnion(near, *whole, {&first, &second}, 1e-13 * size, label);
    } catch (const Error& e) {
        EXPECT_FALSE(whole) << label << ": only the near union refuses: " << e.what();
        EXPECT_EQ(e.message().id, wholeRefusal) << label;
    }
    return 0;
}

}  // namespace rigmesh::testsupport
