// A mesh assembled from separate pieces, each vertex knowing its piece, as
// autorig/RigSurface gives the auto-rig's piece-aware steps their input
// (autorig/HeldProps, autorig/WornPieces); for tests that build figures
// from primitives.
#pragma once

#include <functional>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh::autorigtest {

struct PiecewiseMesh {
    TriMesh mesh;
    std::vector<int> pieceOf;
    int pieces = 0;
};

// Adds `piece` as a new piece, each vertex moved by `place`.
inline void addPiece(PiecewiseMesh& figure, const TriMesh& piece,
                     const std::function<Vec3(const Vec3&)>& place) {
    const int offset = figure.mesh.vertexCount();
    for (const Vec3& v : piece.vertices) {
        figure.mesh.vertices.push_back(place(v));
        figure.pieceOf.push_back(figure.pieces);
    }
    for (const auto& [a, b, c] : piece.faces)
        figure.mesh.faces.push_back({a + offset, b + offset, c + offset});
    ++figure.pieces;
}

}  // namespace rigmesh::autorigtest
