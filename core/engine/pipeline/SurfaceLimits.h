// What a sketch and its build options must satisfy for double precision to
// give a valid mesh of a sane size, each with a message saying what range is
// allowed. Sizes are those of the outline itself, so every bound is relative
// to the input's own scale.
#pragma once

#include "mesh/TriMesh.h"
#include "pipeline/LocalFrame.h"
#include "sketch/StrokeCleaner.h"

namespace rigmesh {

// The most vertices a surface may have: about 20 times a detailed part.
inline constexpr double kMaxSurfaceVertices = 2'000'000;
// Outline sizes (bounding-box diagonals) and coordinates the pipeline
// accepts: their squares and cubes (areas, volumes) stay far inside double's
// range, and the limits cover float32 exports (up to 3.4e38) as well.
inline constexpr double kMinOutlineSize = 1e-50, kMaxOutlineSize = 1e30;
// The finest step the output coordinates must resolve, as a fraction of the
// smallest edge: at most this much rounding where the surface lies.
inline constexpr double kCoordinateResolution = 1e-6;

// Refuses an outline too small or too large, or lying too far from the origin
// for its size (the mesh would have collapsed or non-finite faces). `spacing`
// is the outline's spacing in local units; the edge length budget keeps the
// mesh's edges within a small factor of it.
void checkOutlineScale(const LocalFrame& frame, const CleanPolygon& localOutline, double spacing);

// Refuses an edge length (local units) that would give more than
// kMaxSurfaceVertices vertices on this outline.
void checkEdgeLengthBudget(const LocalFrame& frame, const CleanPolygon& localOutline,
                           double edgeLength);

// Refuses a built mesh with a non-finite coordinate, a degenerate face or
// faces that cross each other (the surface intersects itself: a needle too
// thin for its edge length), saying where. `mirror`, if given, is each
// vertex's image in the sketch plane (SketchSurface::mirror): a surface that
// is exactly its own mirror image is then tested for crossings on about half
// its faces (mesh/MeshSelfIntersections.h), with the same verdict.
void checkBuiltMesh(const TriMesh& mesh, const std::vector<int>& mirror = {});

}  // namespace rigmesh
