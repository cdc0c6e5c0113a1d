// Closed, outward-oriented primitive meshes for tests, benchmarks and as
// starting shapes.
#pragma once

#include "mesh/TriMesh.h"

namespace rigmesh {

// A sphere centred at the origin made by splitting each icosahedron triangle
// into four `subdivisions` times (0..8): 20 * 4^subdivisions faces.
TriMesh makeIcosphere(int subdivisions, double radius);

// A capped cylinder along the z axis from z = -length/2 to z = +length/2 with
// `rings` (>= 2) circles of `segments` (>= 3) vertices and a centre vertex per
// cap: 2 * segments * rings faces.
TriMesh makeCylinderTube(int rings, int segments, double radius, double length);

}  // namespace rigmesh
