// Carries per-vertex part data across a topology edit:
// given where each output vertex came from (VertexSources), the one place
// that moves skin weights, the mirror map and known closest bones to the new
// mesh and lists the vertices whose weights must be computed afresh.
#pragma once

#include <vector>

#include "mesh/TriMesh.h"
#include "part/BoneWeights.h"
#include "part/VertexSource.h"

namespace rigmesh {

// One input of the operation, its bones already given the ids they have in
// the output skeleton.
struct CarrySource {
    const TriMesh* mesh = nullptr;
    WeightsById weights;            // per vertex, or empty
    std::vector<int> mirror;        // per vertex, or empty
    ClosestBonesById knownClosest;  // per vertex, or empty
};

struct CarriedData {
    WeightsById weights;            // per output vertex; empty list = no weights yet
    std::vector<int> mirror;        // empty unless every vertex's mirror image survived
    ClosestBonesById knownClosest;  // copied for unchanged vertices only
    // Vertices that are not an unchanged copy (a point on a source triangle
    // or new): their weights are interpolated or missing and must be solved.
    std::vector<int> needWeights;
};

// Vertex sources copy their vertex's data; triangle sources interpolate the
// weights barycentrically (renormalised) and keep no mirror or closest bone;
// new vertices get nothing.
CarriedData carryAcross(const VertexSources& sources, const std::vector<CarrySource>& inputs);

}  // namespace rigmesh
