// A rigged part: the value every modelling operation takes and returns
// (paper sections 2-3). It is always rigged: surface, skeleton and skin
// weights, plus the per-vertex bookkeeping that local updates (cut, merge,
// bone edits) reuse.
#pragma once

#include <string>
#include <vector>

#include "mesh/TriMesh.h"
#include "rig/BoneHeatSolver.h"
#include "rig/Skeleton.h"
#include "surface/SketchSurface.h"

namespace rigmesh {

struct Part {
    std::string name;
    std::vector<Vec2> outline;  // the cleaned sketch polygon it was built from
    TriMesh mesh;
    std::vector<VertexOrigin> origins;  // per vertex: region and axis position
    std::vector<int> mirror;            // per vertex: its reflection through the sketch plane
    Skeleton skeleton;
    // Per vertex (bone index = position in skeleton.bones()), non-negative,
    // summing to 1.
    SkinWeights weights;
    // Per vertex: the closest bone(s) known at creation (paper 2.4's shortcut
    // for cylindrical vertices); empty where visibility had to be tested.
    ClosestBones knownClosestBones;

    // Bones as segments in the order of skeleton.bones().
    std::vector<BoneSegment> boneSegments() const;
};

}  // namespace rigmesh
