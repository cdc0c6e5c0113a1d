// The figures a sketched surface is judged by: how sharply it creases
// (the angle between the normals of faces sharing an edge) and how well its
// front view matches the sketch (intersection over union of the two
// silhouettes). Measured here so tests, benchmarks and `rigmesh build
// --stats` report the same numbers.
#pragma once

#include <vector>

#include "base/Types.h"
#include "mesh/TriMesh.h"

namespace rigmesh {

struct NormalAngles {
    double p50 = 0, p99 = 0, max = 0;  // degrees, over edges shared by two faces
    Vec3 worstEdgeMidpoint = Vec3::Zero();
    int edges = 0;
};

// Over every edge with exactly two faces (others are left out). Degenerate
// faces (no normal) are left out too.
NormalAngles normalAngles(const TriMesh& mesh);

// Intersection over union of the mesh's silhouette seen along -z (its
// triangles projected onto the xy plane) and the polygon `outline` (xy),
// rasterised on a `resolution` x `resolution` grid over their joint bounding
// box. 1 = the same silhouette. 0 when either is empty.
double silhouetteIoU(const TriMesh& mesh, const std::vector<Vec2>& outline, int resolution = 512);

}  // namespace rigmesh
