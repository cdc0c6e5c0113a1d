// What the proxy wrap (autorig/ProxyWrap) is given: the input's triangles
// with coincident vertices joined, and every border loop closed by a fan
// from its centroid. The wrap itself seals gaps narrower than its alpha, but
// a wider opening (an open-bottomed statue, a bust, a neck hole) would let
// it inside, and the proxy would become a thin shell around both sides of
// the sheet instead of the body's volume. A fan need not be a good surface
// (it may cross the mesh): the wrap takes any soup. The counts are what the
// user is told.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

struct WrapInput {
    TriMesh soup;
    // Per input vertex: the first input vertex at exactly the same position.
    std::vector<int> weldedTo;
    // Per input vertex: its piece (connected by faces over joined
    // vertices), numbered from 0; -1 for a vertex no usable face has.
    std::vector<int> pieceOf;
    int pieces = 0;
    int borderLoops = 0;
    int largestBorderEdges = 0;  // the longest loop, in edges
};

// Faces with a repeated corner (after joining) or a corner out of range
// are left out; the caller has checked positions are finite.
WrapInput wrapInputFor(const TriMesh& input);

}  // namespace rigmesh
