#include "pipeline/SurfaceLimits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Geometry>

#include "base/Error.h"
#include "mesh/MeshChecks.h"
#include "mesh/MeshSelfIntersections.h"

namespace rigmesh {
namespace {

Eigen::AlignedBox2d boxOf(const std::vector<Vec2>& points) {
    Eigen::AlignedBox2d box;
    for (const Vec2& p : points)
        box.extend(p);
    return box;
}

double enclosedArea(const std::vector<Vec2>& polygon) {
    double twiceArea = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec2& a = polygon[i];
        const Vec2& b = polygon[(i + 1) % polygon.size()];
        twiceArea += a.x() * b.y() - a.y() * b.x();
    }
    return 0.5 * std::abs(twiceArea);
}

double perimeter(const std::vector<Vec2>& polygon) {
    double length = 0.0;
    for (std::size_t i = 0; i < polygon.size(); ++i)
        length += (polygon[(i + 1) % polygon.size()] - polygon[i]).norm();
    return length;
}

// Both halves of the surface: each covers the outline's area inflated by up
// to pi/2 (a semicircle over its chord) with a triangular lattice (1 / (h^2
// sqrt(3)/2) vertices per unit area); plus the rings along the outline.
// The suggested smallest edge length is this much above the exact limit, so
// that it passes after being printed with three digits.
constexpr double kEdgeLengthMargin = 1.01;

constexpr double kVerticesPerAreaOverH2 = 2.0 * 1.5707963267948966 / 0.8660254037844386;

double estimatedVertices(double area, double outlineLength, double edgeLength) {
    return kVerticesPerAreaOverH2 * area / (edgeLength * edgeLength) + outlineLength / edgeLength;
}

// The edge length giving exactly `vertices`: the positive root of
// vertices h^2 - L h - k A = 0.
double edgeLengthFor(double vertices, double area, double outlineLength) {
    const double k = kVerticesPerAreaOverH2 * area;
    return (outlineLength + std::sqrt(outlineLength * outlineLength + 4 * vertices * k)) /
           (2 * vertices);
}

}  // namespace

void checkOutlineScale(const LocalFrame& frame, const CleanPolygon& localOutline, double spacing) {
    const Eigen::AlignedBox2d box = boxOf(localOutline.points);
    const double size = box.diagonal().norm() * frame.scale;
    if (!(size >= kMinOutlineSize && size <= kMaxOutlineSize))
        throw Error(MessageId::SketchSizeOutOfRange, shortNumber(size),
                    shortNumber(kMinOutlineSize), shortNumber(kMaxOutlineSize));
    const double farthest = std::max({std::abs(frame.centre.x()), std::abs(frame.centre.y())}) +
                            box.sizes().maxCoeff() * frame.scale;
    const double rounding = farthest * std::numeric_limits<double>::epsilon();
    const double finestEdge = spacing * frame.scale;
    if (!(farthest <= kMaxOutlineSize) || rounding > kCoordinateResolution * finestEdge)
        throw Error(MessageId::SketchTooFarFromOrigin, shortNumber(farthest), shortNumber(rounding),
                    shortNumber(finestEdge),
                    shortNumber(kCoordinateResolution * finestEdge /
                                std::numeric_limits<double>::epsilon()));
}

void checkEdgeLengthBudget(const LocalFrame& frame, const CleanPolygon& localOutline,
                           double edgeLength) {
    const double area = enclosedArea(localOutline.points);
    const double outlineLength = perimeter(localOutline.points);
    const double vertices = estimatedVertices(area, outlineLength, edgeLength);
    if (vertices <= kMaxSurfaceVertices)
        return;
    throw Error(MessageId::EdgeLengthTooSmall, shortNumber(edgeLength * frame.scale),
                shortNumber(vertices), shortNumber(kMaxSurfaceVertices),
                shortNumber(localOutline.spacing * frame.scale),
                shortNumber(kEdgeLengthMargin *
                            edgeLengthFor(kMaxSurfaceVertices, area, outlineLength) * frame.scale));
}

void checkBuiltMesh(const TriMesh& mesh, const std::vector<int>& mirror) {
    for (const Vec3& v : mesh.vertices)
        if (!v.allFinite())
            throw Error(MessageId::SurfaceNotFinite);
    const int degenerate = countDegenerateFaces(mesh);
    if (degenerate > 0)
        throw Error(MessageId::SurfaceDegenerateFaces, degenerate);
    // A surface crossing itself cannot be merged or cut and its own export
    // would be refused by `rigmesh rig`: refused here, where the sketch is.
    const std::vector<std::array<int, 2>> crossing =
        mirror.empty() ? selfIntersectingFacePairs(mesh) : selfIntersectingFacePairs(mesh, mirror);
    if (!crossing.empty()) {
        const auto& face = mesh.faces[static_cast<std::size_t>(crossing.front()[0])];
        const Vec3 near =
            (mesh.vertices[face[0]] + mesh.vertices[face[1]] + mesh.vertices[face[2]]) / 3.0;
        throw Error(MessageId::SurfaceSelfIntersecting, crossing.size(), shortNumber(near.x()),
                    shortNumber(near.y()));
    }
}

}  // namespace rigmesh
