#include "part/CarryAcross.h"

#include <map>
#include <utility>

namespace rigmesh {

CarriedData carryAcross(const VertexSources& sources, const std::vector<CarrySource>& inputs) {
    const int n = static_cast<int>(sources.size());
    CarriedData out;
    out.weights.resize(n);
    out.knownClosest.resize(n);
    // Output index of each unchanged input vertex, for the mirror map.
    std::map<std::pair<int, int>, int> outputOf;
    for (int v = 0; v < n; ++v) {
        const VertexSource& s = sources[v];
        if (s.kind == VertexSource::Kind::Vertex) {
            const CarrySource& in = inputs[s.mesh];
            if (!in.weights.empty())
                out.weights[v] = in.weights[s.index];
            if (!in.knownClosest.empty())
                out.knownClosest[v] = in.knownClosest[s.index];
            outputOf[{s.mesh, s.index}] = v;
            continue;
        }
        out.needWeights.push_back(v);
        if (s.kind != VertexSource::Kind::Triangle || inputs[s.mesh].weights.empty())
            continue;
        const CarrySource& in = inputs[s.mesh];
        const auto& face = in.mesh->faces[s.index];
        for (int c = 0; c < 3; ++c)
            for (const auto& [bone, w] : in.weights[face[c]])
                out.weights[v].emplace_back(bone, s.barycentric[c] * w);
        normaliseWeights(out.weights[v]);
    }
    // The mirror map survives only if every vertex's image did (a merge of
    // parts that share their sketch plane, with no vertex created).
    out.mirror.assign(n, -1);
    for (int v = 0; v < n; ++v) {
        const VertexSource& s = sources[v];
        auto image = s.kind == VertexSource::Kind::Vertex && !inputs[s.mesh].mirror.empty()
                         ? outputOf.find({s.mesh, inputs[s.mesh].mirror[s.index]})
                         : outputOf.end();
        if (image == outputOf.end()) {
            out.mirror.clear();
            break;
        }
        out.mirror[v] = image->second;
    }
    return out;
}

}  // namespace rigmesh
