// Vertex adjacency of an indexed triangle mesh: what graph distances
// (paper 3.2.1 and 3.2.2) and Laplacians walk over.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Per vertex: its neighbours along edges, sorted, each once.
std::vector<std::vector<int>> vertexNeighbours(const TriMesh& mesh);

// The mean length of the faces' edges (inner edges counted twice): a part's
// working edge length when none is given.
double meanEdgeLength(const TriMesh& mesh);

}  // namespace rigmesh
