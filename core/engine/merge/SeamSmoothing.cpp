#include "merge/SeamSmoothing.h"

#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <queue>
#include <set>

#include "mesh/Fairing.h"
#include "mesh/MeshAdjacency.h"

namespace rigmesh {

namespace {

// Per loop vertex: the centroid of its connected loop.
std::map<int, Vec3> loopCentroids(const TriMesh& mesh,
                                  const std::vector<std::array<int, 2>>& loop) {
    std::map<int, int> parent;
    std::function<int(int)> find = [&](int v) {
        while (parent[v] != v)
            v = parent[v] = parent[parent[v]];
        return v;
    };
    for (const auto& [a, b] : loop) {
        parent.try_emplace(a, a);
        parent.try_emplace(b, b);
        parent[find(a)] = find(b);
    }
    std::map<int, std::pair<Vec3, int>> sums;
    for (const auto& [v, unused] : parent) {
        auto& [sum, count] = sums.try_emplace(find(v), Vec3::Zero(), 0).first->second;
        sum += mesh.vertices[v];
        ++count;
    }
    std::map<int, Vec3> centroid;
    for (const auto& [v, unused] : parent) {
        const auto& [sum, count] = sums.at(find(v));
        centroid[v] = sum / count;
    }
    return centroid;
}

}  // namespace

std::vector<int> seamBand(const TriMesh& mesh, const std::vector<std::array<int, 2>>& loop,
                          const SeamSmoothingOptions& options) {
    const int n = mesh.vertexCount();
    const std::vector<std::vector<int>> neighbours = vertexNeighbours(mesh);
    const std::map<int, Vec3> centroid = loopCentroids(mesh, loop);
    // Multi-source Dijkstra over edge lengths, each vertex remembering the
    // loop vertex it is closest to; a vertex is in the band while its
    // distance is below k |v_i - centroid| of that loop vertex v_i.
    std::vector<double> distance(n, std::numeric_limits<double>::infinity());
    std::vector<double> radius(n, 0.0);
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
    for (const auto& [v, c] : centroid) {
        distance[v] = 0.0;
        radius[v] = options.k * (mesh.vertices[v] - c).norm();
        queue.emplace(0.0, v);
    }
    std::vector<int> band;
    std::vector<char> done(n, 0);
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (done[v] || d > distance[v])
            continue;
        done[v] = 1;
        band.push_back(v);
        for (int w : neighbours[v]) {
            const double dw = d + (mesh.vertices[w] - mesh.vertices[v]).norm();
            if (dw < distance[w] && dw < radius[v]) {
                distance[w] = dw;
                radius[w] = radius[v];
                queue.emplace(dw, w);
            }
        }
    }
    std::sort(band.begin(), band.end());
    return band;
}

std::vector<int> smoothSeam(TriMesh& mesh, const std::vector<std::array<int, 2>>& loop,
                            const SeamSmoothingOptions& options) {
    const std::vector<int> band = seamBand(mesh, loop, options);
    if (band.empty() || !fairPositions(mesh, band))
        return {};
    return band;
}

}  // namespace rigmesh
