// The Chordal Axis Transform of a sketched polygon and its pruning
// (paper 2.1, after Prasad 1997 and Teddy).
//
// 1. The CDT's internal edges are chords. A triangle with three chords is a
//    junction, with two a sleeve, with one a terminal.
// 2. The chordal axis joins chord midpoints (and junction centres).
// 3. Insignificant branches are pruned: starting at a terminal triangle we
//    walk inward while every outline point passed so far lies inside the
//    circle whose diameter is the current chord; if the walk reaches a
//    junction, the whole branch is only a bump of the outline and is pruned.
//    Pruning repeats until nothing changes, since a pruned junction becomes a
//    sleeve and may expose a new insignificant branch.
// 4. What is left is a tree of node triangles (junctions and terminals) joined
//    by branches: chains of sleeves crossing an ordered list of chords.
#pragma once

#include <array>
#include <vector>

#include "geometry/ConstrainedTriangulation.h"

namespace rigmesh {

enum class TriangleKind { Terminal, Sleeve, Junction, Isolated };

// An edge of the triangulation as two polygon indices.
using PolygonEdge = std::array<int, 2>;

struct AxisBranch {
    int startNode = -1;        // triangle index of a junction or terminal
    int endNode = -1;          // triangle index of a junction or terminal
    std::vector<int> sleeves;  // sleeve triangles from start to end
    // chords crossed from start to end, each oriented (left, right) with
    // respect to the direction of travel; chords.size() == sleeves.size() + 1
    std::vector<PolygonEdge> chords;
};

struct ChordalAxisOptions {
    // A bump is pruned while its outline stays within this factor of the
    // chord's half-length from the chord's midpoint (1 = Teddy's circle test).
    double pruneCircleFactor = 1.0;
};

struct ChordalAxis {
    PolygonTriangulation cdt;
    std::vector<TriangleKind> kindBeforePruning;  // per triangle
    std::vector<bool> pruned;                     // per triangle
    std::vector<TriangleKind> kind;               // per triangle, after pruning (live ones)
    std::vector<AxisBranch> branches;             // after pruning

    Vec2 centroid(int triangle) const;
    Vec2 midpoint(const PolygonEdge& chord) const;
    double length(const PolygonEdge& chord) const;
    // The live triangle across edge `k` of `triangle`, or -1.
    int liveNeighbor(int triangle, int k) const;
    // Teddy's test: does every outline point of `region` (other than the
    // chord's own end points) lie within `factor` times the chord's half-length
    // of its midpoint?
    bool outlineInsideChordCircle(const std::vector<int>& region, const PolygonEdge& chord,
                                  double factor) const;
};

ChordalAxis computeChordalAxis(PolygonTriangulation cdt, const ChordalAxisOptions& options = {});

// Segments of the chordal axis for drawing: through the live triangles only
// when `afterPruning`, else through all of them.
std::vector<std::array<Vec2, 2>> chordalAxisSegments(const ChordalAxis& axis, bool afterPruning);

}  // namespace rigmesh
