// Both union scopes (merge/MeshUnion.h) on one pair of surfaces: the near
// union gives the whole union's mesh bit for bit (positions, faces, sources,
// loop), or the same refusal.
#pragma once

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "base/Error.h"
#include "merge/MeshUnion.h"

namespace rigmesh::testsupport {

inline void expectSameUnion(const MeshUnionResult& near, const MeshUnionResult& whole,
                            const std::string& label) {
    ASSERT_EQ(near.mesh.vertices.size(), whole.mesh.vertices.size()) << label;
    for (std::size_t v = 0; v < near.mesh.vertices.size(); ++v) {
        ASSERT_EQ(near.mesh.vertices[v], whole.mesh.vertices[v]) << label << " vertex " << v;
        ASSERT_EQ(near.sources[v].kind, whole.sources[v].kind) << label << " vertex " << v;
        ASSERT_EQ(near.sources[v].mesh, whole.sources[v].mesh) << label << " vertex " << v;
        ASSERT_EQ(near.sources[v].index, whole.sources[v].index) << label << " vertex " << v;
        ASSERT_EQ(near.sources[v].barycentric, whole.sources[v].barycentric)
            << label << " vertex " << v;
    }
    EXPECT_EQ(near.mesh.faces, whole.mesh.faces) << label;
    EXPECT_EQ(near.loop, whole.loop) << label;
    EXPECT_EQ(near.onLoop, whole.onLoop) << label;
    EXPECT_EQ(near.remeshedVertices, whole.remeshedVertices) << label;
}

// Both scopes on one pair: the same mesh, or the same refusal.
inline void expectBothScopesAgree(const TriMesh& first, const TriMesh& second, double edge,
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
        ASSERT_TRUE(whole) << label << ": only the near union answers";
        expectSameUnion(near, *whole, label);
    } catch (const Error& e) {
        EXPECT_FALSE(whole) << label << ": only the near union refuses: " << e.what();
        EXPECT_EQ(e.message().id, wholeRefusal) << label;
    }
}

}  // namespace rigmesh::testsupport
