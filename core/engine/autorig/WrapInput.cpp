#include "autorig/WrapInput.h"

#include <algorithm>
#include <map>
#include <unordered_map>
#include <utility>

#include "base/DisjointSets.h"
#include "mesh/PositionHash.h"

namespace rigmesh {

namespace {

struct PositionEqual {
    bool operator()(const Vec3& a, const Vec3& b) const { return a == b; }
};

// The border edges (used by one face) walked into loops; at a vertex where
// several loops meet any pairing will do, and a walk that cannot close is
// kept as an open chain.
std::vector<std::vector<int>> borderLoops(const std::vector<std::array<int, 3>>& faces) {
    std::map<std::pair<int, int>, int> uses;
    for (const auto& face : faces)
        for (int i = 0; i < 3; ++i) {
            const int a = face[i], b = face[(i + 1) % 3];
            ++uses[{std::min(a, b), std::max(a, b)}];
        }
    std::map<int, std::vector<int>> next;
    for (const auto& [edge, count] : uses)
        if (count == 1) {
            next[edge.first].push_back(edge.second);
            next[edge.second].push_back(edge.first);
        }
    std::vector<std::vector<int>> loops;
    const auto take = [&](int from) {
        std::vector<int>& out = next[from];
        const int to = out.back();
        out.pop_back();
        std::vector<int>& back = next[to];
        back.erase(std::find(back.begin(), back.end(), from));
        return to;
    };
    for (auto& [start, around] : next)
        while (!around.empty()) {
            std::vector<int> loop{start};
            int at = take(start);
            while (at != start) {
                loop.push_back(at);
                if (next[at].empty())
                    break;
                at = take(at);
            }
            loops.push_back(std::move(loop));
        }
    return loops;
}

}  // namespace

WrapInput wrapInputFor(const TriMesh& input) {
    WrapInput result;
    const int n = input.vertexCount();
    result.weldedTo.resize(n);
    std::unordered_map<Vec3, int, PositionHash, PositionEqual> firstAt;
    for (int v = 0; v < n; ++v)
        result.weldedTo[v] = firstAt.emplace(input.vertices[v], v).first->second;

    std::vector<std::array<int, 3>> faces;
    for (const auto& face : input.faces) {
        if (std::any_of(face.begin(), face.end(), [&](int c) { return c < 0 || c >= n; }))
            continue;
        const std::array<int, 3> f{result.weldedTo[face[0]], result.weldedTo[face[1]],
                                   result.weldedTo[face[2]]};
        if (f[0] != f[1] && f[1] != f[2] && f[0] != f[2])
            faces.push_back(f);
    }

    // Pieces: faces connected through joined vertices.
    DisjointSets sets(static_cast<std::size_t>(n));
    for (const auto& f : faces) {
        sets.unite(f[0], f[1]);
        sets.unite(f[0], f[2]);
    }
    std::vector<char> used(n, 0);
    for (const auto& f : faces)
        for (int c : f)
            used[c] = 1;
    std::vector<int> pieceOfRoot(n, -1);
    result.pieceOf.assign(n, -1);
    for (int v = 0; v < n; ++v) {
        const int w = result.weldedTo[v];
        if (!used[w])
            continue;
        int& piece = pieceOfRoot[sets.find(w)];
        if (piece < 0)
            piece = result.pieces++;
        result.pieceOf[v] = piece;
    }

    result.soup.vertices = input.vertices;
    result.soup.faces = faces;
    for (const std::vector<int>& loop : borderLoops(faces)) {
        if (loop.size() < 3)
            continue;
        Vec3 centroid = Vec3::Zero();
        for (int v : loop)
            centroid += input.vertices[v];
        const int centre = result.soup.vertexCount();
        result.soup.vertices.push_back(centroid / static_cast<double>(loop.size()));
        for (std::size_t i = 0; i < loop.size(); ++i)
            result.soup.faces.push_back({centre, loop[i], loop[(i + 1) % loop.size()]});
        ++result.borderLoops;
        result.largestBorderEdges =
            std::max(result.largestBorderEdges, static_cast<int>(loop.size()));
    }
    return result;
}

}  // namespace rigmesh
