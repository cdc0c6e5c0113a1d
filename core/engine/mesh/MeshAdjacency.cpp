#include "mesh/MeshAdjacency.h"

#include <algorithm>

namespace rigmesh {

std::vector<std::vector<int>> vertexNeighbours(const TriMesh& mesh) {
    // Each list sized once for the two entries per corner it gets (growing
    // by push_back took five allocations a vertex).
    std::vector<int> corners(mesh.vertices.size(), 0);
    for (const auto& face : mesh.faces)
        for (int v : face)
            ++corners[v];
    std::vector<std::vector<int>> neighbours(mesh.vertices.size());
    for (std::size_t v = 0; v < neighbours.size(); ++v)
        neighbours[v].reserve(2 * static_cast<std::size_t>(corners[v]));
    for (const auto& face : mesh.faces)
        for (int c = 0; c < 3; ++c) {
            neighbours[face[c]].push_back(face[(c + 1) % 3]);
            neighbours[face[c]].push_back(face[(c + 2) % 3]);
        }
    for (auto& list : neighbours) {
        std::sort(list.begin(), list.end());
        list.erase(std::unique(list.begin(), list.end()), list.end());
    }
    return neighbours;
}

double meanEdgeLength(const TriMesh& mesh) {
    double total = 0.0;
    for (const auto& face : mesh.faces)
        for (int c = 0; c < 3; ++c)
            total += (mesh.vertices[face[c]] - mesh.vertices[face[(c + 1) % 3]]).norm();
    return mesh.faces.empty() ? 0.0 : total / (3.0 * mesh.faceCount());
}

}  // namespace rigmesh
