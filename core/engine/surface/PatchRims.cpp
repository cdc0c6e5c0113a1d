#include "surface/PatchRims.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <queue>
#include <utility>

namespace rigmesh {
namespace {

constexpr double kFar = std::numeric_limits<double>::infinity();

std::vector<std::vector<int>> neighbours(const TriMesh& mesh) {
    std::vector<std::vector<int>> ring(mesh.vertices.size());
    for (const auto& f : mesh.faces)
        for (int k = 0; k < 3; ++k)
            ring[f[k]].push_back(f[(k + 1) % 3]);
    return ring;
}

// Distances along the edges (in the sketch plane) from the `sources` through
// the connecting regions' inner vertices, with the value each vertex takes
// from its nearest source.
struct Field {
    std::vector<double> distance;
    std::vector<double> value;
};

Field spread(const SketchSurface& surface, const std::vector<std::vector<int>>& ring,
             const std::vector<std::pair<int, double>>& sources) {
    const auto& origins = surface.origins;
    const auto& positions = surface.mesh.vertices;
    Field field{std::vector<double>(positions.size(), kFar),
                std::vector<double>(positions.size(), 0.0)};
    using Item = std::pair<double, int>;
    std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
    for (const auto& [v, value] : sources) {
        field.distance[v] = 0.0;
        field.value[v] = value;
        queue.push({0.0, v});
    }
    while (!queue.empty()) {
        const auto [d, v] = queue.top();
        queue.pop();
        if (d > field.distance[v])
            continue;
        for (int w : ring[v]) {
            if (origins[w].kind != RegionKind::Connecting || origins[w].onOutline)
                continue;
            const double next = d + (positions[w].head<2>() - positions[v].head<2>()).norm();
            if (next < field.distance[w]) {
                field.distance[w] = next;
                field.value[w] = field.value[v];
                queue.push({next, w});
            }
        }
    }
    return field;
}

}  // namespace

std::vector<double> inflatePatchRims(SketchSurface& surface, const Decomposition& decomposition,
                                     const std::vector<CylinderSections>& cylinders,
                                     double rimWeight, double capPatchWeight) {
    auto& positions = surface.mesh.vertices;
    const auto& origins = surface.origins;
    const int n = static_cast<int>(positions.size());
    std::vector<double> weights(n, 0.0);
    const auto ring = neighbours(surface.mesh);

    // Distance to the outline, and to the nearest port ring with that ring's
    // radius: both measured inside the patches, from their boundaries.
    std::vector<std::pair<int, double>> outline, ports;
    for (int v = 0; v < n; ++v) {
        const VertexOrigin& o = origins[v];
        if (o.onOutline) {
            outline.push_back({v, 0.0});
        } else if (o.kind == RegionKind::Cylindrical && o.section >= 0 &&
                   std::any_of(ring[v].begin(), ring[v].end(),
                               [&](int w) { return origins[w].kind == RegionKind::Connecting; })) {
            ports.push_back({v, cylinders[o.region].sections[o.section].radius()});
        }
    }
    const Field toOutline = spread(surface, ring, outline);
    const Field toPort = spread(surface, ring, ports);

    // A region's thickness R: how far its inside reaches from the outline.
    std::vector<double> thickness(decomposition.connecting.size(), 0.0);
    for (int v = 0; v < n; ++v)
        if (origins[v].kind == RegionKind::Connecting && toOutline.distance[v] < kFar)
            thickness[origins[v].region] =
                std::max(thickness[origins[v].region], toOutline.distance[v]);

    for (int v = 0; v < n; ++v) {
        const VertexOrigin& origin = origins[v];
        if (origin.kind != RegionKind::Connecting || origin.onOutline ||
            surface.mirror[v] < v)  // each pair once, from its upper vertex
            continue;
        // Near a port the cylinder's rings shape the patch (a crotch is close
        // to the outline yet high): the rim is held only a port radius away,
        // and no thicker than the port's ring grows at 45 degrees from it
        // (a shoulder's rim does not rise above its arm).
        const double portRadius = toPort.value[v];
        const double radius =
            portRadius > 0 ? std::min(thickness[origin.region], portRadius + toPort.distance[v])
                           : thickness[origin.region];
        const double d = toOutline.distance[v];
        if (!(radius > 0) || !(d < radius))
            continue;
        const double near =
            portRadius > 0 ? std::clamp(toPort.distance[v] / portRadius - 1.0, 0.0, 1.0) : 1.0;
        const bool capPatch = decomposition.connecting[origin.region].junctions.empty();
        const double w = (capPatch ? capPatchWeight : rimWeight) * (1.0 - d / radius) * near;
        if (!(w > 0))
            continue;
        const double z = std::sqrt(d * (2.0 * radius - d));
        const int mirror = surface.mirror[v];
        positions[v].z() = z;
        positions[mirror].z() = -z;
        weights[v] = weights[mirror] = w;
    }
    return weights;
}

}  // namespace rigmesh
