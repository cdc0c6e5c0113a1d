#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>

#include "base/Error.h"
#include "part/PartDetail.h"

namespace rigmesh {
namespace {

// One vertex's weights by bone id while they are summed.
using SparseWeights = std::map<BoneId, double>;

// One vertex of the next level: a weighted sum of this level's vertices.
using Stencil = std::vector<std::pair<int, double>>;

std::uint64_t edgeKey(int a, int b) {
    if (a > b)
        std::swap(a, b);
    return (std::uint64_t(std::uint32_t(a)) << 32) | std::uint32_t(b);
}

struct Level {
    TriMesh mesh;
    std::vector<Stencil> stencils;  // per new vertex
};

// One round of Loop subdivision, as stencils over the old vertices.
Level loopRound(const TriMesh& mesh) {
    const int n = mesh.vertexCount();
    // Per edge: its two opposite vertices (the second -1 on an open edge).
    std::unordered_map<std::uint64_t, std::pair<int, int>> opposite;
    opposite.reserve(static_cast<std::size_t>(3 * mesh.faceCount()));
    std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(n));
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = f[static_cast<std::size_t>(k)],
                      b = f[static_cast<std::size_t>((k + 1) % 3)];
            const int c = f[static_cast<std::size_t>((k + 2) % 3)];
            auto [it, fresh] = opposite.try_emplace(edgeKey(a, b), c, -1);
            if (!fresh)
                it->second.second = c;
            else {
                neighbours[static_cast<std::size_t>(a)].push_back(b);
                neighbours[static_cast<std::size_t>(b)].push_back(a);
            }
        }

    Level out;
    out.stencils.resize(static_cast<std::size_t>(n));
    std::vector<bool> onBoundary(static_cast<std::size_t>(n), false);
    for (const auto& [key, faces] : opposite)
        if (faces.second < 0) {
            onBoundary[key >> 32] = true;
            onBoundary[key & 0xFFFFFFFFu] = true;
        }
    for (int v = 0; v < n; ++v) {
        const auto& ring = neighbours[static_cast<std::size_t>(v)];
        const int valence = static_cast<int>(ring.size());
        if (onBoundary[static_cast<std::size_t>(v)] || valence < 3) {
            out.stencils[static_cast<std::size_t>(v)] = {{v, 1.0}};
            continue;
        }
        const double beta = valence == 3 ? 3.0 / 16.0 : 3.0 / (8.0 * valence);
        Stencil stencil = {{v, 1.0 - valence * beta}};
        for (int u : ring)
            stencil.emplace_back(u, beta);
        out.stencils[static_cast<std::size_t>(v)] = std::move(stencil);
    }
    std::unordered_map<std::uint64_t, int> edgeVertex;
    edgeVertex.reserve(opposite.size());
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k) {
            const int a = f[static_cast<std::size_t>(k)],
                      b = f[static_cast<std::size_t>((k + 1) % 3)];
            const std::uint64_t key = edgeKey(a, b);
            if (edgeVertex.contains(key))
                continue;
            edgeVertex[key] = static_cast<int>(out.stencils.size());
            const auto [c, d] = opposite.at(key);
            out.stencils.push_back(d < 0 ? Stencil{{a, 0.5}, {b, 0.5}}
                                         : Stencil{{a, 0.375}, {b, 0.375}, {c, 0.125}, {d, 0.125}});
        }
    out.mesh.vertices.resize(out.stencils.size(), Vec3::Zero());
    for (std::size_t v = 0; v < out.stencils.size(); ++v)
        for (const auto& [from, w] : out.stencils[v])
            out.mesh.vertices[v] += w * mesh.vertices[static_cast<std::size_t>(from)];
    out.mesh.faces.reserve(4 * mesh.faces.size());
    for (const auto& f : mesh.faces) {
        const int ab = edgeVertex.at(edgeKey(f[0], f[1]));
        const int bc = edgeVertex.at(edgeKey(f[1], f[2]));
        const int ca = edgeVertex.at(edgeKey(f[2], f[0]));
        out.mesh.faces.push_back({f[0], ab, ca});
        out.mesh.faces.push_back({ab, f[1], bc});
        out.mesh.faces.push_back({ca, bc, f[2]});
        out.mesh.faces.push_back({ab, bc, ca});
    }
    return out;
}

// Weights through the stencils: summed, tiny ones (below 1e-6) dropped, the
// rest renormalised to 1.
SkinWeightsById carriedWeights(const SkinWeightsById& weights,
                               const std::vector<Stencil>& stencils) {
    SkinWeightsById out;
    out.perVertex.reserve(stencils.size());
    for (const Stencil& stencil : stencils) {
        SparseWeights sum;
        for (const auto& [from, w] : stencil)
            for (const auto& [bone, value] : weights.perVertex[static_cast<std::size_t>(from)])
                sum[bone] += w * value;
        double total = 0;
        for (auto it = sum.begin(); it != sum.end();)
            if (it->second < 1e-6) {
                it = sum.erase(it);
            } else {
                total += it->second;
                ++it;
            }
        std::vector<std::pair<BoneId, double>> list;
        for (const auto& [bone, value] : sum)
            list.emplace_back(bone, value / total);
        out.perVertex.push_back(std::move(list));
    }
    out.failedBones = weights.failedBones;
    out.warnings = weights.warnings;
    return out;
}

}  // namespace

Part subdividedPart(const Part& part, int levels) {
    if (levels < 0 || levels > 4)
        throw Error(MessageId::SubdivisionLevelsOutOfRange, levels);
    Part out = part;
    const bool rigged = out.skeleton.boneCount() > 0;
    for (int level = 0; level < levels; ++level) {
        const std::size_t edges = 3 * out.mesh.faces.size() / 2;
        if (out.mesh.vertices.size() + edges > static_cast<std::size_t>(kMaxDetailVertices))
            throw Error(MessageId::SubdivisionTooManyVertices, part.name, levels,
                        kMaxDetailVertices);
        const Level next = loopRound(out.mesh);
        if (rigged)
            out.weights = carriedWeights(out.weights, next.stencils);
        out.mesh = next.mesh;
    }
    if (levels > 0) {
        out.origins.clear();
        out.mirror.clear();
        out.knownClosestBones.clear();
    }
    if (const auto problems = out.validate(); !problems.empty())
        throw Error(MessageId::SubdivisionInvalidResult, part.name, problems.front());
    return out;
}

}  // namespace rigmesh
