// Point-versus-closed-mesh queries written independently of the engine: the
// generalized winding number (sum of the solid angles the triangles subtend,
// over 4 pi; Jacobson et al. 2013) and the exact distance to the surface.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "mesh/TriMesh.h"

namespace rigmesh::parttest {

// Solid angle of triangle abc seen from p (Van Oosterom and Strackee 1983),
// signed positive for a counter-clockwise triangle seen from its back.
inline double solidAngle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 x = a - p;
    const Vec3 y = b - p;
    const Vec3 z = c - p;
    const double lx = x.norm();
    const double ly = y.norm();
    const double lz = z.norm();
    const double numerator = x.dot(y.cross(z));
    const double denominator = lx * ly * lz + x.dot(y) * lz + y.dot(z) * lx + z.dot(x) * ly;
    return 2.0 * std::atan2(numerator, denominator);
}

// About 1 inside a closed outward-oriented mesh, 0 outside.
inline double windingNumber(const TriMesh& mesh, const Vec3& p) {
    double sum = 0.0;
    for (const auto& f : mesh.faces)
        sum += solidAngle(p, mesh.vertices[f[0]], mesh.vertices[f[1]], mesh.vertices[f[2]]);
    return sum / (4.0 * std::numbers::pi);
}

// Closest point of triangle abc to p (Ericson, Real-Time Collision Detection 5.1.5).
inline Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 ab = b - a;
    const Vec3 ac = c - a;
    const Vec3 ap = p - a;
    const double d1 = ab.dot(ap);
    const double d2 = ac.dot(ap);
    if (d1 <= 0 && d2 <= 0)
        return a;
    const Vec3 bp = p - b;
    const double d3 = ab.dot(bp);
    const double d4 = ac.dot(bp);
    if (d3 >= 0 && d4 <= d3)
        return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0)
        return a + d1 / (d1 - d3) * ab;
    const Vec3 cp = p - c;
    const double d5 = ab.dot(cp);
    const double d6 = ac.dot(cp);
    if (d6 >= 0 && d5 <= d6)
        return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0)
        return a + d2 / (d2 - d6) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
    const double denominator = 1.0 / (va + vb + vc);
    return a + ab * (vb * denominator) + ac * (vc * denominator);
}

// Unsigned distance from p to the mesh surface (brute force over triangles).
inline double distanceToSurface(const TriMesh& mesh, const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : mesh.faces) {
        const Vec3 q = closestPointOnTriangle(p, mesh.vertices[f[0]], mesh.vertices[f[1]],
                                              mesh.vertices[f[2]]);
        best = std::min(best, (p - q).norm());
    }
    return best;
}

}  // namespace rigmesh::parttest
