#include "mesh/MeshTopologyCheck.h"

#include <numeric>
#include <vector>

namespace rigmesh {

bool isClosedOrientedManifold(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    if (mesh.faces.empty())
        return false;
    // Each vertex's outgoing edges, packed: the directed edge of face f's
    // corner k (from corner k to corner k + 1) is entry entryOf[3f + k].
    std::vector<int> start(n + 1, 0);
    for (const auto& face : mesh.faces) {
        for (int v : face) {
            if (v < 0 || v >= n)
                return false;
            ++start[v + 1];
        }
        if (face[0] == face[1] || face[1] == face[2] || face[2] == face[0])
            return false;
    }
    std::partial_sum(start.begin(), start.end(), start.begin());
    const std::size_t corners = 3 * mesh.faces.size();
    std::vector<int> to(corners), cornerOf(corners), entryOf(corners);
    std::vector<int> cursor(start.begin(), start.end() - 1);
    for (std::size_t f = 0; f < mesh.faces.size(); ++f)
        for (int k = 0; k < 3; ++k) {
            const int e = cursor[mesh.faces[f][k]]++;
            to[e] = mesh.faces[f][(k + 1) % 3];
            cornerOf[e] = static_cast<int>(3 * f) + k;
            entryOf[3 * f + k] = e;
        }
    // Each directed edge's reverse, which must occur exactly once (an edge
    // used twice one way finds its reverse's reverse twice).
    std::vector<int> reverse(corners);
    for (int v = 0; v < n; ++v)
        for (int e = start[v]; e < start[v + 1]; ++e) {
            const int w = to[e];
            int found = -1;
            for (int r = start[w]; r < start[w + 1]; ++r)
                if (to[r] == v) {
                    if (found >= 0)
                        return false;
                    found = r;
                }
            if (found < 0)
                return false;
            reverse[e] = found;
        }
    // One fan around each vertex: from face (v, w, x) the next face around v
    // leaves along v -> x, the reverse of that face's edge x -> v.
    for (int v = 0; v < n; ++v) {
        const int degree = start[v + 1] - start[v];
        if (degree == 0)
            continue;
        int e = start[v], steps = 0;
        do {
            const int corner = cornerOf[e];
            const int into = entryOf[corner - corner % 3 + (corner + 2) % 3];
            e = reverse[into];
            if (++steps > degree)
                return false;
        } while (e != start[v]);
        if (steps != degree)
            return false;
    }
    return true;
}

}  // namespace rigmesh
