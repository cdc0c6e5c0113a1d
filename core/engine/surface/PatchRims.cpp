#include "surface/PatchRims.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "sketch/PolygonGeometry.h"

namespace rigmesh {
namespace {

// The mean radius of the cylinder ends meeting each connecting region.
std::vector<double> regionThickness(const Decomposition& decomposition,
                                    const std::vector<CylinderSections>& cylinders) {
    std::vector<double> sum(decomposition.connecting.size(), 0.0);
    std::vector<int> count(decomposition.connecting.size(), 0);
    for (std::size_t c = 0; c < cylinders.size(); ++c) {
        const CylinderRegion& region = decomposition.cylinders[c];
        if (region.startConnecting >= 0) {
            sum[region.startConnecting] += cylinders[c].sections.front().radius();
            ++count[region.startConnecting];
        }
        if (region.endConnecting >= 0) {
            sum[region.endConnecting] += cylinders[c].sections.back().radius();
            ++count[region.endConnecting];
        }
    }
    for (std::size_t r = 0; r < sum.size(); ++r)
        sum[r] = count[r] > 0 ? sum[r] / count[r] : 0.0;
    return sum;
}

// The chords where cylinders meet each connecting region (their end sections).
std::vector<std::vector<CrossSection>> regionPorts(const Decomposition& decomposition,
                                                   const std::vector<CylinderSections>& cylinders) {
    std::vector<std::vector<CrossSection>> ports(decomposition.connecting.size());
    for (std::size_t c = 0; c < cylinders.size(); ++c) {
        const CylinderRegion& region = decomposition.cylinders[c];
        if (region.startConnecting >= 0)
            ports[region.startConnecting].push_back(cylinders[c].sections.front());
        if (region.endConnecting >= 0)
            ports[region.endConnecting].push_back(cylinders[c].sections.back());
    }
    return ports;
}

}  // namespace

std::vector<double> inflatePatchRims(SketchSurface& surface, const Decomposition& decomposition,
                                     const std::vector<CylinderSections>& cylinders,
                                     double rimWeight) {
    auto& positions = surface.mesh.vertices;
    const int n = static_cast<int>(positions.size());
    std::vector<double> weights(n, 0.0);
    const std::vector<double> thickness = regionThickness(decomposition, cylinders);

    // The outline as the polygon's segments (the surface's outline vertices
    // lie on them).
    const auto& outline = decomposition.axis.cdt.points;
    const int m = static_cast<int>(outline.size());
    auto distanceToOutline = [&](const Vec2& p, double limit) {
        double best = limit;
        for (int i = 0; i < m; ++i)
            best = std::min(best, distanceToSegment(p, outline[i], outline[(i + 1) % m]));
        return best;
    };
    const auto ports = regionPorts(decomposition, cylinders);
    for (int v = 0; v < n; ++v) {
        const VertexOrigin& origin = surface.origins[v];
        if (origin.kind != RegionKind::Connecting || origin.onOutline ||
            surface.mirror[v] < v)  // each pair once, from its upper vertex
            continue;
        const double radius = thickness[origin.region];
        if (!(radius > 0))
            continue;
        const double d = distanceToOutline(positions[v].head<2>(), radius);
        if (d >= radius)
            continue;
        // Near a port the cylinder's rings shape the patch (a crotch is close
        // to the outline yet high): the rim is held only a radius away.
        double port = 2.0 * radius;
        for (const CrossSection& s : ports[origin.region])
            port = std::min(port, distanceToSegment(positions[v].head<2>(), s.left, s.right));
        const double z = std::sqrt(d * (2.0 * radius - d));
        const double w = rimWeight * (1.0 - d / radius) * std::clamp(port / radius - 1.0, 0.0, 1.0);
        if (!(w > 0))
            continue;
        const int mirror = surface.mirror[v];
        positions[v].z() = z;
        positions[mirror].z() = -z;
        weights[v] = weights[mirror] = w;
    }
    return weights;
}

}  // namespace rigmesh
