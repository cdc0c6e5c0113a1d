#include "rig/VertexMirror.h"

#include "mesh/MeshAdjacency.h"
#include "mesh/VertexTree.h"

namespace rigmesh {

double vertexMirrorTolerance(const TriMesh& mesh) {
    return 0.5 * meanEdgeLength(mesh);
}

std::vector<int> mirrorVertices(const TriMesh& mesh, const MirrorPlane& plane, double tolerance) {
    const int n = mesh.vertexCount();
    const VertexTree tree(mesh.vertices);
    // Each vertex's nearest to its reflection, then kept where it is mutual.
    std::vector<int> nearest(n, kNoMirrorVertex);
    for (int v = 0; v < n; ++v) {
        const Vec3 reflected = plane.reflect(mesh.vertices[v]);
        const int w = tree.nearest(reflected);
        if (w >= 0 && (mesh.vertices[w] - reflected).norm() <= tolerance)
            nearest[v] = w;
    }
    std::vector<int> partner(n, kNoMirrorVertex);
    for (int v = 0; v < n; ++v)
        if (nearest[v] != kNoMirrorVertex && nearest[nearest[v]] == v)
            partner[v] = nearest[v];
    return partner;
}

}  // namespace rigmesh
