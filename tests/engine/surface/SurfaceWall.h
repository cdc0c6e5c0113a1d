// A wall in an inflated surface: a steep face (its normal within 15 degrees
// of the sketch plane) whose projection lies well inside the outline. An
// inflated surface is steep only at its rim, which stands on the outline;
// where the surface cuts across a bump of the outline it leaves out (a short
// limb the skeleton prunes) the front and back halves meet along the cut in
// a steep strip with a sharp rim, and where a low patch meets a high body it
// steps down in one. The figure is how far inside the outline the deepest
// steep face's centre lies, so it catches a step that keeps the silhouette.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "mesh/TriMesh.h"
#include "sketch/PolygonGeometry.h"

namespace rigmesh::surfacetest {

struct Wall {
    double depth = 0;  // inside the outline, of the deepest steep face's centre
    Vec2 where = Vec2::Zero();
};

inline Wall deepestWall(const TriMesh& mesh, const std::vector<Vec2>& outline,
                        double steepDegrees = 75.0) {
    const double flatness = std::cos(steepDegrees * M_PI / 180.0);  // |n.z| below: steep
    Wall wall;
    const std::size_t n = outline.size();
    for (const auto& face : mesh.faces) {
        const Vec3 &a = mesh.vertices[face[0]], &b = mesh.vertices[face[1]],
                   &c = mesh.vertices[face[2]];
        const Vec3 normal = (b - a).cross(c - a);
        if (normal.norm() == 0 || std::abs(normal.normalized().z()) >= flatness)
            continue;
        const Vec2 centre = ((a + b + c) / 3.0).head<2>();
        if (!insidePolygon(outline, centre))
            continue;
        double nearest = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < n && nearest > wall.depth; ++k)
            nearest =
                std::min(nearest, distanceToSegment(centre, outline[k], outline[(k + 1) % n]));
        if (nearest > wall.depth) {
            wall.depth = nearest;
            wall.where = centre;
        }
    }
    return wall;
}

}  // namespace rigmesh::surfacetest
