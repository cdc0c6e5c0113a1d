// Meshes that are exactly their own mirror image in the plane z = 0, as the
// sketch surfaces are by construction (surface/SketchSurface.h: the upper
// half built, then mirrored through the sketch plane).
#pragma once

#include <optional>
#include <vector>

#include "mesh/TriMesh.h"

namespace rigmesh {

// Per face, the face on the images of its corners, when `mirror` (each
// vertex's image, as SketchSurface::mirror gives it) makes the mesh exactly
// its own mirror image: mirror is an involution, every vertex's image sits at
// (x, y, -z) bit for bit (a vertex on the plane is its own image), and every
// face has a face on its corners' images whose image it is in turn (so no
// face is listed twice). Otherwise nothing.
std::optional<std::vector<int>> mirrorFaceImages(const TriMesh& mesh,
                                                 const std::vector<int>& mirror);

}  // namespace rigmesh
