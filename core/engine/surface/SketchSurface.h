// The 3D surface inflated from a decomposed sketch (paper 2.2, Fig. 3).
//
// The surface is built as its upper half (z >= 0) and mirrored through the
// sketch plane, so it is closed and exactly mirror-symmetric by construction:
//  - each cylindrical region becomes a generalized cylinder: semicircles over
//    its cross sections, stitched by triangle strips, ending in a tip point at
//    a cap;
//  - each connecting region is covered by a planar patch bounded by the
//    outline and the semicircles of the cylinders that meet there (our
//    replacement for the paper's semicircle lines + strips + GridMesh: a
//    triangular lattice plus a constrained Delaunay triangulation), lifted
//    later by the smoothing step;
//  - Least-Squares Meshes then smooth the whole surface: connecting vertices
//    are free, cylinder vertices are anchored with weights that grow with
//    their distance along the axis from the nearest connecting region.
#pragma once

#include <cstdint>
#include <vector>

#include "mesh/TriMesh.h"
#include "surface/CrossSections.h"

namespace rigmesh {

enum class RegionKind : std::uint8_t { Cylindrical, Connecting };

// Where a vertex came from: what the rig and later local updates need.
struct VertexOrigin {
    RegionKind kind = RegionKind::Cylindrical;
    int region = -1;   // index of the cylindrical or connecting region
    int section = -1;  // cross-section index in the cylinder; -1 at a tip or in a connecting region
    double axisPosition = 0.0;  // arc length along the cylinder's axis (cylindrical vertices)
    bool onOutline = false;     // on the sketch outline, i.e. on the mirror plane
};

struct SketchSurface {
    TriMesh mesh;
    std::vector<VertexOrigin> origins;  // per vertex
    std::vector<int> mirror;            // per vertex: its reflection through the sketch plane
};

struct SurfaceOptions {
    double targetEdgeLength = 0.0;  // required, > 0
    bool smooth = true;             // run Least-Squares Meshes
    double maxAnchorWeight = 10.0;  // anchor weight far from any connecting region
    // Distance (in mean cylinder diameters) over which anchor weights rise
    // from 0 at a connecting region to maxAnchorWeight.
    double anchorFalloff = 1.0;
    // Anchor weight of a cap's vertices off the outline: low, so
    // LSM smooths the tips.
    double capAnchorWeight = 1.0;
};

SketchSurface buildSurface(const Decomposition& decomposition,
                           const std::vector<CylinderSections>& cylinders,
                           const SurfaceOptions& options);

// The Least-Squares Meshes step of buildSurface (paper 2.2, Fig. 3f) on its
// own, for callers that time it separately: buildSurface with `smooth` off,
// then this, gives what buildSurface with `smooth` on gives.
void smoothSurface(SketchSurface& surface, const Decomposition& decomposition,
                   const std::vector<CylinderSections>& cylinders, const SurfaceOptions& options);

}  // namespace rigmesh
