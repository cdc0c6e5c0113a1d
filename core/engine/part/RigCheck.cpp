#include "part/RigCheck.h"

#include <cmath>

#include "base/Error.h"
#include "part/BoneWeights.h"

namespace rigmesh {

RigCheckReport checkRig(const Part& part, const RigCheckOptions& options) {
    if (options.maxInfluences < 1 || !(options.sumTolerance > 0.0))
        throw Error(MessageId::RigCheckOptionsInvalid);
    RigCheckReport report;
    const int vertexCount = part.mesh.vertexCount();
    const auto& weights = part.weights.perVertex;
    for (int v = 0; v < vertexCount; ++v) {
        if (v >= static_cast<int>(weights.size()) || weights[v].empty()) {
            report.unweightedVertices.push_back(v);
            continue;
        }
        double sum = 0.0;
        for (const auto& entry : weights[v])
            sum += entry.second;
        if (static_cast<int>(weights[v].size()) > options.maxInfluences)
            report.verticesOverInfluences.push_back(v);
        if (!(std::abs(sum - 1.0) <= options.sumTolerance))
            report.verticesWithSumsOff.push_back(v);
    }
    const std::map<BoneId, int> leading = leadingVertexCounts(part.weights.perVertex);
    for (const Bone& bone : part.skeleton.bones())
        if (!leading.contains(bone.id))
            report.bonesLeadingNoVertex.push_back(bone.id);
    return report;
}

}  // namespace rigmesh
