// Decomposition of the sketch into cylindrical and connecting regions
// (paper 2.1, Fig. 2 c-d).
//
// Each branch of the pruned chordal axis becomes a cylindrical region, except
// short-yet-wide branches between two junctions, which would give flat,
// disc-like surfaces: those are merged with their junctions into one larger
// connecting region. A branch that ends in a terminal triangle gets a cap:
// the terminal triangle grown inward (Teddy's fan) while the outline stays
// within the circle of the next chord, so the tip is a dome, not a wiggle.
#pragma once

#include <vector>

#include "axis/ChordalAxis.h"

namespace rigmesh {

struct CylinderRegion {
    std::vector<PolygonEdge> chords;  // (left, right) for travel from start to end; never empty
    int startConnecting = -1;         // connecting region at the start, or -1 for a cap
    int endConnecting = -1;           // connecting region at the end, or -1 for a cap
    int startJunction = -1;           // the junction triangle the start leaves from, or -1
    int endJunction = -1;             // the junction triangle the end arrives at, or -1
    // Counter-clockwise outline paths (polygon indices) around the tips, from
    // one end point of the end chord to the other; empty at a connecting end.
    std::vector<int> startCap;  // from chords.front() left to right
    std::vector<int> endCap;    // from chords.back() right to left
};

struct ConnectingRegion {
    std::vector<int> junctions;  // junction triangles
    std::vector<int> triangles;  // all triangles: junctions, merged sleeves, pruned bumps
    // Pairs of junction triangles joined by a merged short-yet-wide branch.
    std::vector<std::array<int, 2>> junctionLinks;
    struct Port {
        int cylinder;
        bool atStart;  // the cylinder's start (true) or end (false) touches this region
    };
    std::vector<Port> ports;
};

struct DecompositionOptions {
    ChordalAxisOptions axis;
    // A branch between two junctions shorter than this factor times its mean
    // chord length is "short-yet-wide" and merged into the connecting region.
    double mergeLengthFactor = 1.0;
    // Circle factor of the cap growth test (1 = Teddy's circle).
    double capCircleFactor = 1.0;
    // A pruned bump off a body sleeve whose outline reaches this factor times
    // the outline's spacing (the 90th percentile of its edges) from its chord
    // becomes a connecting region (axis/BodyBumps.h); lower ones are left to
    // the body's cross sections. Infinite: none (the rig's decomposition).
    double bumpHeightFactor = 1.5;
};

struct Decomposition {
    ChordalAxis axis;
    std::vector<CylinderRegion> cylinders;
    std::vector<ConnectingRegion> connecting;
};

Decomposition decompose(ChordalAxis axis, const DecompositionOptions& options = {});

}  // namespace rigmesh
