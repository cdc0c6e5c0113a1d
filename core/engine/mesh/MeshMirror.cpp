#include "mesh/MeshMirror.h"

namespace rigmesh {

std::optional<std::vector<int>> mirrorFaceImages(const TriMesh& mesh,
                                                 const std::vector<int>& mirror) {
    const int n = mesh.vertexCount();
    if (static_cast<int>(mirror.size()) != n)
        return std::nullopt;
    for (int v = 0; v < n; ++v) {
        const int m = mirror[v];
        if (m < 0 || m >= n || mirror[m] != v)
            return std::nullopt;
        const Vec3& p = mesh.vertices[v];
        const Vec3& q = mesh.vertices[m];
        if (!(q.x() == p.x() && q.y() == p.y() && q.z() == -p.z()))
            return std::nullopt;
    }
    // Faces around each vertex, packed; a face's image is among those
    // around the image of its first corner.
    const int faceTotal = mesh.faceCount();
    std::vector<int> first(static_cast<std::size_t>(n) + 1, 0);
    for (const auto& f : mesh.faces)
        for (int v : f) {
            if (v < 0 || v >= n)
                return std::nullopt;
            ++first[v + 1];
        }
    for (int v = 0; v < n; ++v)
        first[v + 1] += first[v];
    std::vector<int> around(first.back());
    std::vector<int> fill(first.begin(), first.end() - 1);
    for (int i = 0; i < faceTotal; ++i)
        for (int v : mesh.faces[i])
            around[fill[v]++] = i;
    const auto hasCorner = [&](int face, int v) {
        const auto& f = mesh.faces[face];
        return f[0] == v || f[1] == v || f[2] == v;
    };
    std::vector<int> image(faceTotal, -1);
    for (int i = 0; i < faceTotal; ++i) {
        const auto& f = mesh.faces[i];
        const int a = mirror[f[0]], b = mirror[f[1]], c = mirror[f[2]];
        for (int k = first[a]; k < first[a + 1] && image[i] < 0; ++k)
            if (hasCorner(around[k], b) && hasCorner(around[k], c))
                image[i] = around[k];
        if (image[i] < 0)
            return std::nullopt;
    }
    return image;
}

}  // namespace rigmesh
