// A plane's cut through a limb, for autorig/FusedLimbs: where the plane
// through a point of a leaf chain, across it, cuts the proxy (its outlines
// around the chain) and the mesh the part keeps (its outlines inside the
// proxy's there). Internal to the auto-rig.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// The mesh with coincident vertices joined, so that a plane cuts a seamed
// limb in one connected outline.
struct Welded {
    std::vector<Vec3> points;
    std::vector<std::array<int, 3>> faces;
    std::vector<int> of;  // per mesh vertex, its point
};

Welded weld(const TriMesh& mesh);

struct Segment {
    Vec3 a, b;
    std::uint64_t keyA, keyB;  // the mesh edges its ends lie on
};

struct Outline {
    Vec3 centroid = Vec3::Zero();
    double length = 0.0;
    std::vector<int> members;  // its segments
};

// The proxy's cut through p perpendicular to d, and its outlines around
// the chain there: the innermost one around p or, where the chain runs
// outside the proxy (a straight bone across a gap the proxy has open), the
// outlines about as near as the nearest.
struct ProxyCut {
    Vec3 u, v;
    std::vector<Segment> segments;
    std::vector<Outline> outlines;
    std::vector<int> around;

    // Inside the proxy: within an odd number of its outlines (a cavity's
    // outline lies inside the outer one), and within one around the chain.
    bool holds(const Vec3& q) const;
    // The farthest point of the outlines around the chain from p.
    double reach(const Vec3& p) const;
};

ProxyCut proxyCutAt(const Welded& proxy, const Vec3& p, const Vec3& d);

// The mesh's outlines in the plane through `p` perpendicular to `d`, inside
// the proxy's outlines around the chain there (`faces`: those of the
// mesh's that may reach them): those comparable with the longest.
std::vector<Outline> limbsAt(const Welded& mesh, const std::vector<std::array<int, 3>>& faces,
                             const ProxyCut& proxyCut, const Vec3& p, const Vec3& d);

}  // namespace rigmesh
