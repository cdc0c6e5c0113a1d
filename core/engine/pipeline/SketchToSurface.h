// Sketch to surface, the whole of paper sections 2.1-2.2 in one call:
// clean stroke -> CDT -> chordal axis (pruned) -> decomposition into
// cylindrical and connecting regions -> cross sections -> surface -> LSM.
#pragma once

#include <optional>
#include <vector>

#include "axis/Decomposition.h"
#include "sketch/StrokeCleaner.h"
#include "surface/SketchSurface.h"

namespace rigmesh {

struct SketchToSurfaceOptions {
    StrokeCleanOptions stroke;
    DecompositionOptions decomposition;
    CrossSectionOptions sections;
    SurfaceOptions surface;  // targetEdgeLength 0 = the cleaned outline's spacing
};

// Milliseconds spent in each stage. `surface` builds the mesh, `smoothing`
// runs Least-Squares Meshes on it, `checks` moves the result back to the
// world and refuses a mesh with a non-finite coordinate or a degenerate face.
struct StageTimings {
    double clean = 0, triangulate = 0, chordalAxis = 0, decompose = 0, crossSections = 0,
           surface = 0, smoothing = 0, checks = 0, total = 0;
};

struct SketchToSurfaceResult {
    CleanPolygon polygon;
    Decomposition decomposition;              // the rig's regions (paper 2.1)
    std::vector<CylinderSections> cylinders;  // the rig's sections
    // What the surface was built on, where it differs from the rig's: its
    // regions when they differ (concave corners rounded, pruned bumps off
    // bodies as connecting regions, cap bases moved), else empty; and its
    // sections (also snapped to the outline near fixed end chords).
    std::optional<Decomposition> surfaceRegions;
    std::vector<CylinderSections> surfaceCylinders;
    SketchSurface surface;
    double targetEdgeLength = 0;
    StageTimings milliseconds;
};

// Throws rigmesh::Error with a user-readable reason on bad input: besides a
// bad stroke, an outline whose size or position double precision cannot
// build (SurfaceLimits.h) or an edge length giving too many vertices.
SketchToSurfaceResult sketchToSurface(const std::vector<Vec2>& stroke,
                                      const SketchToSurfaceOptions& options = {});

}  // namespace rigmesh
