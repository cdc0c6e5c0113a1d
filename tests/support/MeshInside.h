// Point-versus-closed-mesh queries written independently of the engine: the
// generalized winding number (sum of the solid angles the triangles subtend,
// over 4 pi; Jacobson et al. 2013), the exact distance to the surface, and
// ray-cast parity as tests/external/check_tails_inside_in_blender.py asks it.
#pragma once

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

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

// Where the ray p + t d (t >= 0) meets triangle abc, or -1 (Moller and
// Trumbore 1997).
inline double rayHitsTriangle(const Vec3& p, const Vec3& d, const Vec3& a, const Vec3& b,
                              const Vec3& c) {
    const Vec3 e1 = b - a;
    const Vec3 e2 = c - a;
    const Vec3 h = d.cross(e2);
    const double det = e1.dot(h);
    if (std::abs(det) < 1e-300)
        return -1.0;
    const Vec3 s = p - a;
    const double u = s.dot(h) / det;
    const Vec3 q = s.cross(e1);
    const double v = d.dot(q) / det;
    if (u < 0.0 || v < 0.0 || u + v > 1.0)
        return -1.0;
    const double t = e2.dot(q) / det;
    return t >= 0.0 ? t : -1.0;
}

// Inside by ray-cast parity, as check_tails_inside_in_blender.py decides
// what Blender shows: three rays in fixed directions each cross the surface
// (every mesh piece, overlapping or not) an odd or even number of times,
// crossings closer together than 1e-5 of `size` counting once; inside when
// most are odd. A point inside an eye inside a head is outside.
inline bool insideByRayParity(const TriMesh& mesh, const Vec3& p, double size) {
    const Vec3 rays[] = {Vec3(0.267, 0.534, 0.802).normalized(), Vec3(-0.7, 0.1, 0.3).normalized(),
                         Vec3(0.2, -0.9, -0.35).normalized()};
    int odd = 0;
    for (const Vec3& d : rays) {
        std::vector<double> hits;
        for (const auto& f : mesh.faces) {
            const double t = rayHitsTriangle(p, d, mesh.vertices[f[0]], mesh.vertices[f[1]],
                                             mesh.vertices[f[2]]);
            if (t >= 0.0)
                hits.push_back(t);
        }
        std::sort(hits.begin(), hits.end());
        int crossings = 0;
        double last = -std::numeric_limits<double>::infinity();
        for (double t : hits)
            if (t > last + 1e-5 * size) {
                ++crossings;
                last = t;
            }
        odd += crossings % 2;
    }
    return 2 * odd > 3;
}

}  // namespace rigmesh::parttest
