#include "autorig/WeightTransfer.h"

#include "mesh/CgalSurfaceMesh.h"

namespace rigmesh {

WeightsById weightsAtClosestPoints(const TriMesh& surface, const WeightsById& weights,
                                   const std::vector<Vec3>& points,
                                   const std::vector<char>& wanted) {
    WeightsById result(points.size());
    const cgal::SourceTriangles triangles({&surface});
    for (std::size_t p = 0; p < points.size(); ++p) {
        if (!wanted.empty() && !wanted[p])
            continue;
        const VertexSource source = triangles.sourceOf(points[p]);
        const auto& corners = surface.faces[source.index];
        auto& list = result[p];
        for (int i = 0; i < 3; ++i)
            for (const auto& [bone, weight] : weights[corners[i]])
                list.emplace_back(bone, source.barycentric[i] * weight);
        normaliseWeights(list);
    }
    return result;
}

}  // namespace rigmesh
