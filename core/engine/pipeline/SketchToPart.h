// Sketch to rigged part: paper sections 2.1-2.4 in one call. The surface
// (SketchToSurface.h), then the skeleton (2.3) and bone heat skin weights
// (2.4), using the closest bones known from the surface's construction for
// cylindrical vertices.
#pragma once

#include "part/Part.h"
#include "pipeline/SketchToSurface.h"
#include "rig/SkeletonFromRegions.h"

namespace rigmesh {

struct SketchToPartOptions {
    SketchToSurfaceOptions surface;
    SkeletonOptions skeleton;
    BoneHeatOptions weights;
    // A symmetric outline gets mirrored joints (rig/SkeletonSymmetry).
    bool mirrorJoints = true;
};

struct SketchToPartResult {
    SketchToSurfaceResult surface;
    PartSkeleton skeleton;
    Part part;
    double skeletonMilliseconds = 0;
    double weightsMilliseconds = 0;
    double totalMilliseconds = 0;
};

// Throws rigmesh::Error with a user-readable reason on bad input.
SketchToPartResult sketchToPart(const std::vector<Vec2>& stroke, const std::string& name,
                                const SketchToPartOptions& options = {});

// The closest bones of cylindrical vertices, known from where each vertex was
// created (paper 2.4), with ties within `tieTolerance` as the solver's
// visibility test lists them; other vertices get an empty list.
ClosestBones closestBonesFromConstruction(const SketchSurface& surface,
                                          const std::vector<CylinderSections>& cylinders,
                                          const PartSkeleton& skeleton,
                                          double tieTolerance = BoneHeatOptions{}.tieTolerance);

}  // namespace rigmesh
