// Where a vertex of a mesh made from other meshes came from:
// the bookkeeping every topology edit (merge 3.2, cut 3.1, bone edits 3.3)
// returns so that skin weights and other per-vertex data can follow it.
// Idiom: geometry-central's surgery returns maps back to the old mesh; CGAL's
// corefinement tells a visitor where faces came from.
#pragma once

#include <array>
#include <vector>

#include "base/Types.h"

namespace rigmesh {

struct VertexSource {
    enum class Kind {
        Vertex,    // a copy of vertex `index` of source mesh `mesh`
        Triangle,  // a point on face `index` of source mesh `mesh`, at `barycentric`
        New,       // no source: its data must be computed afresh
    };
    Kind kind = Kind::New;
    int mesh = -1;   // which of the operation's input meshes
    int index = -1;  // vertex or face index in that mesh
    Vec3 barycentric = Vec3::Zero();

    static VertexSource vertex(int mesh, int index) {
        return {Kind::Vertex, mesh, index, Vec3::Zero()};
    }
    static VertexSource triangle(int mesh, int face, const Vec3& barycentric) {
        return {Kind::Triangle, mesh, face, barycentric};
    }
};

using VertexSources = std::vector<VertexSource>;

}  // namespace rigmesh
