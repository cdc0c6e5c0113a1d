// Relaxing the folds Least-Squares Meshes leaves (after paper 2.2).
//
// LSM's uniform Laplacian evens out edge lengths but does not bound the
// angle between neighbouring faces. Where the surface must turn sharply in
// little room it leaves a fold of 40 to 100 degrees in a handful of faces:
// where a limb's port ring meets the outline at a concave corner (a crotch,
// the gap between fingers or tentacles), in a patch next to a tight concave
// arc of the outline, where a limb meets a body at a shallow angle. Around
// each such fold the vertices off the outline are moved to lower the sum of
// (1 - cos theta)^3 over the edges there (theta the angle between the
// normals of an edge's two faces; the cube weighs the worst edges most):
// the surface turns over the fold's neighbourhood instead of at one edge.
// The mirror symmetry stays exact, and so does the outline (the silhouette)
// unless a fold above the limit is left at an outline vertex: a slot's apex
// where the outline turns 150 degrees within a spacing, a hair-thin tip.
// There the outline's turn itself is the fold, and the outline vertices
// around it move too, within the sketch plane and at most `outlineShift`
// (a fillet just where the faces need it). Only a surface with a fold
// above the figures' limit (35 degrees) is touched, so one that meets it
// keeps its vertices bit for bit.
#pragma once

#include "surface/SketchSurface.h"

namespace rigmesh {

struct FoldRelaxationOptions {
    // Nothing moves unless some neighbouring faces meet at more than this
    // (the surface figures' limit, tests/engine/surface/SurfaceFiguresTest).
    double limitDegrees = 35.0;
    double foldDegrees = 25.0;  // then edges whose faces meet at more than this are folds
    int rings = 2;              // vertices this many edges around a fold move too
    int passes = 30;            // rounds of one descent step per moving vertex
    // If a fold is still above the limit after that, the outline vertices
    // around it move too, in the sketch plane, at most this far from where
    // they were built (0: the outline stays exact).
    double outlineShift = 0.0;
};

// Returns how many vertices moved (with their mirror images, counted once).
int relaxFolds(SketchSurface& surface, const FoldRelaxationOptions& options = {});

}  // namespace rigmesh
