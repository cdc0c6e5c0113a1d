#include "mesh/MeshMirror.h"

#include <array>

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
    const int faceTotal = mesh.faceCount();
    for (const auto& f : mesh.faces)
        for (int v : f)
            if (v < 0 || v >= n)
                return std::nullopt;
    const auto isImageOf = [&](int face, const std::array<int, 3>& f) {
        const auto& g = mesh.faces[face];
        const auto has = [&](int v) { return g[0] == v || g[1] == v || g[2] == v; };
        return has(mirror[f[0]]) && has(mirror[f[1]]) && has(mirror[f[2]]);
    };
    // A mesh built as a half and its image (surface/SketchSurface.h) lists
    // the images in the faces' order: the face after the previous face's
    // image is tried first, then the face half the list away. Else the
    // faces around each vertex, packed, are searched: a face's image is
    // among those around the image of its first corner (built on the first
    // miss only).
    std::vector<int> first, around;
    const auto searchAround = [&](const std::array<int, 3>& f) {
        if (first.empty()) {
            first.assign(static_cast<std::size_t>(n) + 1, 0);
            for (const auto& g : mesh.faces)
                for (int v : g)
                    ++first[v + 1];
            for (int v = 0; v < n; ++v)
                first[v + 1] += first[v];
            around.resize(first.back());
            std::vector<int> fill(first.begin(), first.end() - 1);
            for (int i = 0; i < faceTotal; ++i)
                for (int v : mesh.faces[i])
                    around[fill[v]++] = i;
        }
        const int a = mirror[f[0]];
        for (int k = first[a]; k < first[a + 1]; ++k)
            if (isImageOf(around[k], f))
                return around[k];
        return -1;
    };
    std::vector<int> image(faceTotal, -1);
    for (int i = 0; i < faceTotal; ++i) {
        const auto& f = mesh.faces[i];
        const int next = i > 0 ? image[i - 1] + 1 : faceTotal;
        const int across = (i + faceTotal / 2) % faceTotal;
        if (next < faceTotal && isImageOf(next, f))
            image[i] = next;
        else if (isImageOf(across, f))
            image[i] = across;
        else
            image[i] = searchAround(f);
        if (image[i] < 0)
            return std::nullopt;
    }
    // Each face the image of its image: a face listed twice is no one's (a
    // face's image is one face on its corners' images).
    for (int i = 0; i < faceTotal; ++i)
        if (image[image[i]] != i)
            return std::nullopt;
    return image;
}

}  // namespace rigmesh
